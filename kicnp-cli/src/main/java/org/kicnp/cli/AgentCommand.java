package org.kicnp.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Callable;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentOptions;
import org.kicnp.cli.platform.PlatformConfig;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.core.xml.SourcedFrame;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.ScopeType;
import picocli.CommandLine.Spec;

/**
 * {@code kicnp agent}: a person's (or a shell script's) way into a running server, in the manner of ROS's
 * {@code rostopic} and {@code rosservice}: it connects as an agent of the agent file (by default {@code director}, a
 * user agent the platform itself never uses), does one thing through the {@link AgentBase} SDK — query, ask, assert,
 * destroy, watch changes, relay a message, command a robot — prints the answer and disconnects. Everything goes
 * through the gateway's wire protocol with the agent's own token, so the server's checks apply as to any agent.
 */
@Command(name = "agent", mixinStandardHelpOptions = true,
        description = "Talk to a running server as an agent: query and change its knowledge, ask it to prove and "
                + "explain, watch changes, relay messages, send sensor signals, record and play them back, command "
                + "robots and cancel commands. "
                + "Connects with a token "
                + "of the agent file (serve writes it to KB_DIR/.kicnp/agents.properties), as 'director' unless --as "
                + "says otherwise.",
        subcommands = {
            AgentQuestions.Query.class,
            AgentQuestions.Ask.class,
            AgentQuestions.Prove.class,
            AgentQuestions.Why.class,
            AgentQuestions.WhyNot.class,
            AgentCommand.Assert.class,
            AgentCommand.Destroy.class,
            AgentCommand.Watch.class,
            AgentCommand.Send.class,
            AgentSensor.Sensor.class,
            AgentBag.Record.class,
            AgentPlay.class,
            AgentActions.Order.class,
            AgentActions.Cancel.class,
        },
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {
            "0:done",
            "1:the server refused, did not answer, or a command failed",
            "2:wrong usage (also an unreadable agent file or an agent missing from it)"
        })
public final class AgentCommand {
    private static final String QUIET_SDK = "org.slf4j.simpleLogger.log.org.kicnp.agent";

    @Option(names = "--gateway", paramLabel = "HOST:PORT",
            defaultValue = "127.0.0.1:" + PlatformConfig.DEFAULT_GATEWAY_PORT, scope = ScopeType.INHERIT,
            description = "The server, host:port (default ${DEFAULT-VALUE}, where serve listens by default).")
    String gateway;

    @Option(names = "--tokens", defaultValue = "agents.properties", paramLabel = "FILE", scope = ScopeType.INHERIT,
            description = "Agent file with NAME.token (and NAME.kinds) lines (default ${DEFAULT-VALUE}; serve writes "
                    + "it to KB_DIR/.kicnp/agents.properties).")
    Path tokens;

    @Option(names = "--as", defaultValue = "director", paramLabel = "NAME", scope = ScopeType.INHERIT,
            description = "The agent to connect as (default ${DEFAULT-VALUE}). A connection under a name already "
                    + "connected replaces that one, so do not borrow a running robot's or user's name.")
    String as;

    @Option(names = "--timeout", defaultValue = "10", paramLabel = "SECONDS", scope = ScopeType.INHERIT,
            description = "How long to wait to connect, and for each answer (default ${DEFAULT-VALUE}).")
    double timeoutSeconds;

    @Mixin
    TlsTrustOptions tls;

    @Spec
    CommandSpec spec;

    /** Connects as the chosen agent, with {@code hooks} for what the server pushes. */
    CliAgent connect(CommandSpec caller, Hooks hooks) {
        return connect(caller, as, hooks);
    }

    /** Connects as the agent {@code name} of the agent file, with {@code hooks} for what the server pushes. */
    CliAgent connect(CommandSpec caller, String name, Hooks hooks) {
        // The SDK logs its connection's life (registered, reconnecting, refused) for a long-running agent; here
        // the command line says what happened itself.
        if (System.getProperty(QUIET_SDK) == null) {
            System.setProperty(QUIET_SDK, "off");
        }
        GatewayAddress address;
        try {
            address = GatewayAddress.parse(gateway);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(caller.commandLine(), e.getMessage());
        }
        requirePositive(caller, "--timeout", timeoutSeconds);
        Properties file = agentFile(caller);
        String token = file.getProperty(name + ".token", "").strip();
        if (token.isEmpty()) {
            throw new ParameterException(caller.commandLine(), "The agent file '" + tokens + "' has no '" + name
                    + ".token'.");
        }
        AgentKind kind = kindOf(file.getProperty(name + ".kinds", "user"));
        Duration timeout = timeout();
        AgentOptions options = AgentOptions.of(address.host(), address.port(), name, kind, token);
        try {
            options = tls.socketFactory().map(options::withSocketFactory).orElse(options);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(caller.commandLine(), e.getMessage());
        }
        options = options.withRequestTimeout(timeout);
        CliAgent agent = new CliAgent(options, hooks);
        try {
            agent.startAndAwait(timeout);
        } catch (RuntimeException e) {
            agent.close();
            throw e;
        }
        return agent;
    }

    /** The agent file's entries; a usage error when it is missing or unreadable. */
    Properties agentFile(CommandSpec caller) {
        try {
            return AgentFile.read(tokens);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(caller.commandLine(), e.getMessage());
        }
    }

    /** True when {@code --as} was given on the command line (not its default). */
    boolean asGiven() {
        for (picocli.CommandLine c = spec.commandLine(); c != null; c = c.getParent()) {
            // Set on the agent command or, inherited, on any subcommand below it.
            if (c.getParseResult() != null && hasAs(c.getParseResult())) {
                return true;
            }
        }
        return false;
    }

    private static boolean hasAs(picocli.CommandLine.ParseResult r) {
        for (picocli.CommandLine.ParseResult p = r; p != null; p = p.subcommand()) {
            if (p.hasMatchedOption("--as")) {
                return true;
            }
        }
        return false;
    }

    /** A usage error unless {@code seconds} is a number above 0 (not NaN, not infinite). */
    static void requirePositive(CommandSpec caller, String option, double seconds) {
        if (!(seconds > 0) || Double.isInfinite(seconds)) {
            throw new ParameterException(caller.commandLine(), option + " must be a number of seconds above 0, not "
                    + seconds + ".");
        }
    }

    /** A usage error unless {@code name} is an agent name the protocol takes. */
    static void requireAgentName(CommandSpec caller, String what, String name) {
        if (!Message.NAME.matcher(name).matches()) {
            throw new ParameterException(caller.commandLine(), what + " '" + name + "' is not an agent name: use "
                    + "letters, digits, '_' and '-', starting with a letter or '_'.");
        }
    }

    private static AgentKind kindOf(String kinds) {
        String first = kinds.split(",", 2)[0].strip().toUpperCase(Locale.ROOT);
        try {
            return AgentKind.valueOf(first);
        } catch (IllegalArgumentException e) {
            return AgentKind.USER;
        }
    }

    Duration timeout() {
        return Duration.ofMillis(Math.round(timeoutSeconds * 1000));
    }

    /** What every subcommand has: the {@code agent} command's options and a connection made with them. */
    abstract static class Subcommand implements Callable<Integer> {
        @ParentCommand AgentCommand agent;
        @Spec CommandSpec spec;

        /** Connects as the agent the options name, with {@code hooks} for what the server pushes. */
        final CliAgent connect(Hooks hooks) {
            return agent.connect(spec, hooks);
        }
    }

    /** What the server pushes to the agent: change notifications and relays, on the SDK's event thread. */
    record Hooks(java.util.function.Consumer<Message.Changed> changed,
                 java.util.function.Consumer<Message.Relay> relayed) {
        static final Hooks NONE = new Hooks(c -> { }, r -> { });
    }

    /** The agent a command line runs as. */
    static final class CliAgent extends AgentBase {
        private final Hooks hooks;

        CliAgent(AgentOptions options, Hooks hooks) {
            super(options);
            this.hooks = hooks;
        }

        @Override protected void onChanged(Message.Changed change) {
            hooks.changed().accept(change);
        }

        @Override protected void onRelay(Message.Relay relay) {
            hooks.relayed().accept(relay);
        }
    }

    /** NAME=VALUE arguments as a map, in order; a usage error names one that is not. */
    static Map<String, String> pairs(CommandSpec spec, List<String> args) {
        Map<String, String> named = new LinkedHashMap<>();
        for (String arg : args) {
            int eq = arg.indexOf('=');
            if (eq < 1) {
                throw new ParameterException(spec.commandLine(), "Argument '" + arg + "' is not NAME=VALUE.");
            }
            named.put(arg.substring(0, eq), arg.substring(eq + 1));
        }
        return named;
    }

    @Command(name = "assert", mixinStandardHelpOptions = true,
            description = "Add (or replace) instance frames: XML files, or XML text starting with '<'. The frames are "
                    + "read here first (a slot without a TYPE takes the type the server's classes declare; a mistake "
                    + "is "
                    + "reported at its line and nothing is sent), then sent in one assert: the server stores them all "
                    + "as runtime instances, or none (it refuses to replace classes and declared knowledge).")
    static final class Assert extends Subcommand {

        @Parameters(arity = "1..*", paramLabel = "FILE_OR_XML", description = "Instance frames to assert.")
        List<String> sources;

        @Override public Integer call() {
            PrintWriter out = spec.commandLine().getOut();
            try (CliAgent a = connect(Hooks.NONE)) {
                // The server's classes, so that a slot written without its type takes the type declared above it,
                // as the server would read it, and a mistake is reported at its line before anything is sent.
                KnowledgeBase context = KnowledgeBase.create();
                context.apply(a.pull(Optional.empty()).stream().map(f -> (Change) new Change.Put(f)).toList());
                List<Frame> frames = new ArrayList<>();
                Map<String, String> where = new LinkedHashMap<>(); // each frame's location, to name a repeated one
                for (int i = 0; i < sources.size(); i++) {
                    String source = sources.get(i);
                    List<SourcedFrame> parsed = source.stripLeading().startsWith("<")
                            ? KnowledgeLoader.parseText(source, "argument " + (i + 1), context)
                            : KnowledgeLoader.parse(List.of(Path.of(source)), context);
                    for (SourcedFrame s : parsed) {
                        if (!s.frame().isInstance()) {
                            throw new IllegalArgumentException("'" + s.frame().name() + "' (" + s.location()
                                    + ") is a class; assert takes instance frames.");
                        }
                        String first = where.putIfAbsent(s.frame().name(), s.location().toString());
                        if (first != null) {
                            throw new IllegalArgumentException("Frame '" + s.frame().name() + "' is given twice, at "
                                    + first + " and at " + s.location() + "; nothing was sent.");
                        }
                        frames.add(s.frame());
                    }
                }
                a.assertFrames(frames);
                for (Frame f : frames) {
                    out.println("Asserted '" + f.name() + "' (" + f.parent().orElse("?") + ").");
                }
            }
            return 0;
        }
    }

    @Command(name = "destroy", mixinStandardHelpOptions = true,
            description = "Remove instance frames, one after the other (what rests on them goes too).")
    static final class Destroy extends Subcommand {

        @Parameters(arity = "1..*", paramLabel = "NAME", description = "Instances to remove.")
        List<String> names;

        @Override public Integer call() {
            try (CliAgent a = connect(Hooks.NONE)) {
                for (String name : names) {
                    a.destroy(name);
                    spec.commandLine().getOut().println("Destroyed '" + name + "'.");
                }
            }
            return 0;
        }
    }

    @Command(name = "watch", mixinStandardHelpOptions = true,
            description = "Print each change to frames of the classes (and below them), and each message relayed to "
                    + "this agent, as one JSON line: {\"time\", \"event\": added|replaced|removed|relay, \"class\", "
                    + "\"name\", \"frame_class\", \"slots\": {slot: value}} or {\"time\", \"event\": \"relay\", "
                    + "\"from\", \"subject\", \"body\"}. Runs until interrupted, --for seconds, or --count events.")
    static final class Watch extends Subcommand {

        @Parameters(arity = "1..*", paramLabel = "CLASS", description = "Classes to watch.")
        List<String> classes;

        @Option(names = "--for", paramLabel = "SECONDS", description = "Stop after this many seconds.")
        Double seconds;

        @Option(names = "--count", paramLabel = "N", description = "Stop after N events.")
        Integer count;

        @Override public Integer call() throws InterruptedException {
            if (seconds != null) {
                requirePositive(spec, "--for", seconds);
            }
            if (count != null && count < 1) {
                throw new ParameterException(spec.commandLine(), "--count must be 1 or more, not " + count + ".");
            }
            BlockingQueue<String> lines = new LinkedBlockingQueue<>();
            PrintWriter out = spec.commandLine().getOut();
            long deadline = seconds == null ? Long.MAX_VALUE : System.nanoTime() + Math.round(seconds * 1e9);
            Hooks print = new Hooks(c -> lines.add(AgentJson.change(c)), r -> lines.add(AgentJson.relay(r)));
            try (CliAgent a = connect(print)) {
                for (String c : classes) {
                    try {
                        a.subscribe(c);
                    } catch (org.kicnp.agent.NotConnectedException e) {
                        if (a.stopped().isEmpty()) {
                            throw e;
                        }
                        return stopped(a); // replaced while it subscribed
                    }
                }
                spec.commandLine().getErr().println("Watching " + String.join(", ", classes) + " as '" + a.name()
                        + "'.");
                spec.commandLine().getErr().flush();
                int printed = 0;
                while (count == null || printed < count) {
                    long left = deadline - System.nanoTime();
                    if (left <= 0) {
                        break;
                    }
                    String line = lines.poll(Math.min(left, TimeUnit.SECONDS.toNanos(1)), TimeUnit.NANOSECONDS);
                    if (line != null) {
                        out.println(line);
                        out.flush();
                        printed++;
                    } else if (a.stopped().isPresent()) {
                        return stopped(a);
                    }
                }
            }
            return 0;
        }

        /** Says why the watch stopped for good: most often another command connected under the same name. */
        private int stopped(CliAgent a) {
            spec.commandLine().getErr().println("kicnp agent watch: " + a.stopped().orElseThrow().getMessage()
                    + " To watch while other commands run, watch as another agent of the agent file (--as).");
            return 1;
        }
    }

    @Command(name = "send", mixinStandardHelpOptions = true,
            description = "Relay a message to an agent by name, or with --kind to every agent of a kind.")
    static final class Send extends Subcommand {

        @Option(names = "--kind", paramLabel = "KIND",
                description = "Send to every registered agent of this kind (robot, user, service, peer) instead.")
        AgentKind kind;

        @Parameters(paramLabel = "TO SUBJECT BODY", arity = "2..3",
                description = "The agent (left out with --kind), the subject and the body.")
        List<String> words;

        @Override public Integer call() {
            int want = kind == null ? 3 : 2;
            if (words.size() != want) {
                throw new ParameterException(spec.commandLine(), kind == null
                        ? "send takes AGENT SUBJECT BODY (or --kind KIND SUBJECT BODY)."
                        : "With --kind, send takes SUBJECT BODY.");
            }
            try (CliAgent a = connect(Hooks.NONE)) {
                if (kind == null) {
                    a.relayTo(words.get(0), words.get(1), words.get(2));
                } else {
                    a.relayToKind(kind, words.get(0), words.get(1));
                }
            }
            spec.commandLine().getOut().println("Relayed to " + (kind == null ? "'" + words.get(0) + "'"
                    : "every " + kind.name().toLowerCase(Locale.ROOT) + " agent") + ".");
            return 0;
        }
    }
}
