package org.kicnp.cli;

import static org.kicnp.cli.AgentCommand.requirePositive;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.TreeMap;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.NotConnectedException;
import org.kicnp.agent.RequestRefusedException;
import org.kicnp.cli.AgentCommand.CliAgent;
import org.kicnp.cli.AgentCommand.Hooks;
import org.kicnp.cli.AgentCommand.Subcommand;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.protocol.ChangeKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.FrameText;
import org.kicnp.protocol.Message;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;

/**
 * {@code kicnp agent record} and {@code play}: the robots' sensor stream written to a file (a {@link Bag}) as the
 * server receives it, and sent again later, with the recorded spacing, to a server whose rules may have changed — in
 * the manner of {@code rosbag record} and {@code rosbag play}.
 */
final class AgentBag {
    static final String SENSOR_SIGNAL = "SensorSignal";
    /**
     * This machine's clock (epoch milliseconds), read where a server's clock cannot be had; tests set it apart from
     * the server's to show which one a recording's times come from.
     */
    static volatile LongSupplier wallClock = System::currentTimeMillis;

    private AgentBag() {
    }

    @Command(name = "record", mixinStandardHelpOptions = true,
            description = "Record every sensor signal the server receives (changes of SensorSignal instances, and of "
                    + "the other CLASSes named) into FILE, one JSON line each, flushed as it is written: first a "
                    + "header {\"format\": \"kicnp-bag\", \"version\": 1, \"started\", \"gateway\", \"classes\"}, then "
                    + "{\"t\" (ms since the start), \"event\": added|replaced, \"agent\", \"sensor\", \"values\", "
                    + "\"ttlMs\" (when it had one)}, the signals already there first, as added at t 0 (with what was "
                    + "left of their time to live), {\"t\", \"event\": \"removed\", \"agent\", \"sensor\"} when a signal "
                    + "goes (its agent left, it expired, it was destroyed), and {\"t\", \"event\", \"instance\", "
                    + "\"class\", \"frame\"} for a frame that is no signal. Runs until interrupted, --for seconds, or "
                    + "--count lines. 'agent play' sends it again.")
    static final class Record extends Subcommand {

        @Option(names = "--out", required = true, paramLabel = "FILE", description = "The file to write (replaced).")
        Path out;

        @Parameters(arity = "0..*", paramLabel = "CLASS",
                description = "Classes to record (default: SensorSignal). Frames that are no signals are kept as XML "
                        + "for reading beside them; play does not send them.")
        List<String> classes = new ArrayList<>();

        @Option(names = "--for", paramLabel = "SECONDS", description = "Stop after this many seconds.")
        Double seconds;

        @Option(names = "--count", paramLabel = "N",
                description = "Stop after N lines (the header and the signals already there not counted).")
        Integer count;

        /** A change and when it was heard (System.nanoTime). */
        private record Heard(long at, Message.Changed change) {
        }

        @Override public Integer call() throws InterruptedException, IOException {
            if (seconds != null) {
                requirePositive(spec, "--for", seconds);
            }
            if (count != null && count < 1) {
                throw new ParameterException(spec.commandLine(), "--count must be 1 or more, not " + count + ".");
            }
            List<String> recorded = classes.isEmpty() ? List.of(SENSOR_SIGNAL) : List.copyOf(classes);
            BlockingQueue<Heard> heard = new LinkedBlockingQueue<>();
            PrintWriter err = spec.commandLine().getErr();
            long deadline = seconds == null ? Long.MAX_VALUE : System.nanoTime() + Math.round(seconds * 1e9);
            try (CliAgent a = connect(new Hooks(c -> heard.add(new Heard(System.nanoTime(), c)), r -> { }))) {
                long start = System.nanoTime();
                Instant started = Instant.now();
                for (String c : recorded) {
                    try {
                        subscribe(a, c);
                    } catch (NotConnectedException e) {
                        if (a.stopped().isEmpty()) {
                            throw e;
                        }
                        return stopped(a.stopped().get()); // replaced while it subscribed
                    }
                }
                // Read after subscribing, so that a change in between is in the snapshot, heard, or both; never lost.
                Signals signals = new Signals(err);
                List<Bag.Signal> present = snapshot(a, recorded, signals, err);
                // Opened only now, so that a server that cannot be reached or refuses leaves an earlier file as it was.
                try (BufferedWriter file = open(out)) {
                    write(file, new Bag.Header(started, agent.gateway, recorded));
                    present.forEach(p -> write(file, p));
                    err.println("Recording " + String.join(", ", recorded) + " to " + out + " as '" + a.name() + "'.");
                    if (!present.isEmpty()) {
                        err.println(present.size() + " signal" + (present.size() == 1 ? "" : "s")
                                + " there at the start recorded at t=0.");
                    }
                    err.flush();
                    return record(a, heard, file, signals, start, deadline);
                }
            }
        }

        /**
         * The signals of the recorded classes there are now, as lines at t=0, so that playing the bag starts from the
         * state the recording started in (as {@code rosbag} users expect), not from the first change after it. Their
         * values are asked for typed (a frame's XML holds them as text); a signal gone before it is asked for is
         * left out, its removal being heard. Ordered by instance name, so the same state makes the same lines.
         */
        private static List<Bag.Signal> snapshot(CliAgent a, List<String> recorded, Signals signals,
                PrintWriter err) {
            Map<String, Frame> byName = new TreeMap<>();
            Map<String, Long> readAt = new HashMap<>(); // the server's clock when it read the frame
            boolean toldClock = false;
            for (String c : recorded) {
                long local = wallClock.getAsLong();
                AgentBase.Snapshot answer = a.snapshot(c);
                if (answer.serverTime().isEmpty() && !toldClock) {
                    err.println("The server does not say its clock (it predates 'frames' with 'time'): the times to "
                            + "live of the signals there at the start are reckoned on this machine's clock.");
                    toldClock = true;
                }
                long at = answer.serverTime().orElse(local);
                for (Frame f : answer.frames()) { // a frame of two recorded classes comes twice: the later read wins
                    byName.put(f.name(), f);
                    readAt.put(f.name(), at);
                }
            }
            List<Bag.Signal> present = new ArrayList<>();
            for (Frame f : byName.values()) {
                signals.known(f); // to name the agent and sensor of a signal that goes
                if (Signals.signal(f).isEmpty()) {
                    continue;
                }
                Optional<Value> values;
                try {
                    values = a.ask(f.name(), "values");
                } catch (RequestRefusedException e) {
                    if (e.code() != ErrorCode.UNKNOWN_FRAME) {
                        throw e;
                    }
                    continue;
                }
                long now = readAt.get(f.name());
                values.flatMap(v -> Signals.present(f, v, now)).ifPresent(present::add);
            }
            return present;
        }

        /** Writes each change heard as a line until --count, --for, or the connection is lost for good. */
        private int record(CliAgent a, BlockingQueue<Heard> heard, BufferedWriter file, Signals signals, long start,
                           long deadline) throws InterruptedException {
            int written = 0;
            Message.Changed last = null;
            while (count == null || written < count) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    break;
                }
                Heard h = heard.poll(Math.min(left, TimeUnit.SECONDS.toNanos(1)), TimeUnit.NANOSECONDS);
                if (h == null) {
                    if (a.stopped().isPresent()) {
                        return stopped(a.stopped().get());
                    }
                    continue;
                }
                // One change of a frame in two recorded classes (a class and one above it) comes once per class.
                Message.Changed same = new Message.Changed("", h.change().change(), h.change().name(),
                        h.change().frame(), h.change().values());
                if (same.equals(last)) {
                    continue;
                }
                last = same;
                write(file, signals.line(Math.max(0, (h.at() - start) / 1_000_000), h.change()));
                written++;
            }
            spec.commandLine().getErr().println("Recorded " + written + " line" + (written == 1 ? "" : "s") + " to "
                    + out + ".");
            return 0;
        }

        /** Subscribes to a class; a clear word when it is SensorSignal and the server has none. */
        private static void subscribe(CliAgent a, String ofClass) {
            try {
                a.subscribe(ofClass);
            } catch (RequestRefusedException e) {
                if (e.code() == ErrorCode.UNKNOWN_FRAME && ofClass.equals(SENSOR_SIGNAL)) {
                    throw new RequestRefusedException(e.code(), e.getMessage() + " A server whose knowledge base does "
                            + "not declare SensorSignal adds it with the first signal it receives; declare it, or "
                            + "start recording after the first signal.");
                }
                throw e;
            }
        }

        private BufferedWriter open(Path file) {
            try {
                return Files.newBufferedWriter(file, StandardCharsets.UTF_8);
            } catch (IOException e) {
                throw new ParameterException(spec.commandLine(), "Cannot write --out '" + file + "': " + e + ".");
            }
        }

        /** Writes a line and flushes it, so a recording cut short (Ctrl-C) ends with a whole line. */
        private static void write(BufferedWriter file, Bag.Line line) {
            try {
                file.write(Bag.write(line));
                file.newLine();
                file.flush();
            } catch (IOException e) {
                throw new UncheckedIOException("Could not write the recording: " + e.getMessage() + ".", e);
            }
        }

        private int stopped(Exception why) {
            spec.commandLine().getErr().println("kicnp agent record: " + why.getMessage() + " To record while other "
                    + "commands run, record as another agent of the agent file (--as).");
            return 1;
        }
    }

    /** The agent and sensor a signal's instance is of. */
    private record Source(String agent, String sensor) {
    }

    /** What the recorder knows of the signals it has seen: whose each one is, to name it when it goes. */
    private static final class Signals {
        private final Map<String, Source> byName = new HashMap<>();
        private final PrintWriter err;
        private boolean warned;

        Signals(PrintWriter err) {
            this.err = err;
        }

        void known(Frame f) {
            signal(f).ifPresent(s -> byName.put(f.name(), s));
        }

        /**
         * A signal there when the recording started, as an added line at t=0: its values as the server holds them,
         * and as time to live what was left of it at {@code now} (epoch ms on the server's clock, the clock of its
         * {@code expires}: when the server read it), so that played it expires where it would have, whatever this
         * machine's clock says. Empty when it has no values list.
         */
        static Optional<Bag.Signal> present(Frame f, Value values, long now) {
            if (!(values instanceof Value.Lst list)) {
                return Optional.empty();
            }
            Source s = signal(f).orElseThrow();
            Optional<Long> left = integer(f, "expires")
                    .map(e -> Math.clamp(e - now, 1, Message.SensorSignal.MAX_TTL_MS));
            return Optional.of(new Bag.Signal(0, ChangeKind.ADDED, s.agent(), s.sensor(), list.items(), left));
        }

        Bag.Line line(long t, Message.Changed c) {
            if (c.change() == ChangeKind.REMOVED) {
                Source r = byName.remove(c.name());
                return r == null ? new Bag.FrameChange(t, c.change(), c.name(), Optional.empty(), Optional.empty())
                        : new Bag.Removal(t, r.agent(), r.sensor());
            }
            Frame f = FrameText.parse(c.frame().orElseThrow(), "change of '" + c.name() + "'", KnowledgeBase.create())
                    .getFirst();
            Optional<Source> signal = signal(f);
            if (signal.isEmpty() || (c.values().isEmpty() && f.ownSlot("values").isEmpty())) {
                byName.remove(c.name());
                return new Bag.FrameChange(t, c.change(), c.name(), f.parent(), c.frame());
            }
            byName.put(c.name(), signal.get());
            Optional<Long> ttl = integer(f, "expires").flatMap(e -> integer(f, "time").map(at -> e - at));
            return new Bag.Signal(t, c.change(), signal.get().agent(), signal.get().sensor(), values(f, c), ttl);
        }

        /** The values as the server sent them typed; from an older server, as the frame's text. */
        private List<Value> values(Frame f, Message.Changed c) {
            if (c.values().isPresent()) {
                return c.values().get();
            }
            if (!warned) {
                err.println("kicnp agent record: the server sends no typed values with its changes (it is older "
                        + "than this kicnp); values are recorded as the text of the frame's 'values' list.");
                err.flush();
                warned = true;
            }
            return f.ownSlot("values").flatMap(Slot::value)
                    .map(v -> v instanceof Value.Lst l ? l.items() : List.of(v)).orElse(List.of());
        }

        /** The agent and sensor of a sensor signal's frame (its slots 'source' and 'sensor'). */
        private static Optional<Source> signal(Frame f) {
            Optional<String> source = text(f, "source");
            Optional<String> sensor = text(f, "sensor");
            if (source.isEmpty() || sensor.isEmpty() || !Message.NAME.matcher(source.get()).matches()
                    || !Message.NAME.matcher(sensor.get()).matches()) {
                return Optional.empty();
            }
            return Optional.of(new Source(source.get(), sensor.get()));
        }

        private static Optional<String> text(Frame f, String slot) {
            return f.ownSlot(slot).flatMap(Slot::value).filter(v -> v instanceof Value.Str).map(Value::text);
        }

        private static Optional<Long> integer(Frame f, String slot) {
            return f.ownSlot(slot).flatMap(Slot::value).filter(v -> v instanceof Value.Int)
                    .map(v -> ((Value.Int) v).value());
        }
    }

    @Command(name = "play", mixinStandardHelpOptions = true,
            description = "Send the signals of a recording (agent record) again, with the recorded spacing: each as "
                    + "the agent that sent it (its token from the agent file; with --as NAME, all as NAME), with its "
                    + "time to live (scaled by --rate as the spacing is); a recorded "
                    + "removal destroys that agent's signal (the protocol has no message to withdraw one), with what "
                    + "was derived from it. The whole file is read first: a bad line is a usage error naming "
                    + "FILE:LINE, and nothing is sent. Frames that are no signals are not sent. When play ends its "
                    + "agents disconnect, so the server retracts the signals they left. Prints a summary line.")
    static final class Play extends Subcommand {

        @Parameters(index = "0", paramLabel = "FILE", description = "The recording.")
        Path file;

        @Option(names = "--rate", defaultValue = "1", paramLabel = "FACTOR",
                description = "Play this many times faster (default ${DEFAULT-VALUE}; 0.5 is half speed).")
        double rate;

        @Option(names = "--loop", defaultValue = "1", paramLabel = "N",
                description = "Play the recording N times, each round after the last (default ${DEFAULT-VALUE}).")
        int loops;

        @Option(names = "--as-recorded",
                description = "Send each signal as the agent that sent it (the default; --as NAME sends all as NAME).")
        boolean asRecorded;

        @Override public Integer call() throws InterruptedException {
            if (!(rate > 0) || Double.isInfinite(rate)) {
                throw new ParameterException(spec.commandLine(), "--rate must be a number above 0, not " + rate + ".");
            }
            if (loops < 1) {
                throw new ParameterException(spec.commandLine(), "--loop must be 1 or more, not " + loops + ".");
            }
            boolean oneAgent = agent.asGiven();
            if (oneAgent && asRecorded) {
                throw new ParameterException(spec.commandLine(), "Give --as NAME or --as-recorded, not both.");
            }
            Bag.Recording bag;
            try {
                bag = Bag.read(file);
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage());
            }
            Map<String, Integer> agents = agentsOf(bag, oneAgent);
            Properties tokens = agent.agentFile(spec);
            agents.forEach((name, line) -> {
                if (tokens.getProperty(name + ".token", "").isBlank()) {
                    throw new ParameterException(spec.commandLine(), "The agent file '" + agent.tokens + "' has no '"
                            + name + ".token' for agent '" + name + "' (" + file + ":" + line + "); nothing was sent.");
                }
            });
            Map<String, CliAgent> connected = new LinkedHashMap<>();
            try {
                for (String name : agents.keySet()) {
                    connected.put(name, agent.connect(spec, name, Hooks.NONE));
                }
                return play(bag, connected, oneAgent);
            } finally {
                connected.values().forEach(CliAgent::close);
            }
        }

        /** The agents to connect as, each with the first line that needs it. */
        private Map<String, Integer> agentsOf(Bag.Recording bag, boolean oneAgent) {
            Map<String, Integer> agents = new LinkedHashMap<>();
            for (Bag.Numbered n : bag.lines()) {
                String who = switch (n.line()) {
                    case Bag.Signal s -> s.agent();
                    case Bag.Removal r -> r.agent();
                    case Bag.Header h -> null;
                    case Bag.FrameChange f -> null;
                };
                if (who != null) {
                    agents.putIfAbsent(oneAgent ? agent.as : who, n.number());
                }
            }
            return agents;
        }

        private int play(Bag.Recording bag, Map<String, CliAgent> connected, boolean oneAgent)
                throws InterruptedException {
            PrintWriter err = spec.commandLine().getErr();
            long span = bag.lines().isEmpty() ? 0 : Bag.time(bag.lines().getLast().line());
            int signals = 0;
            int removals = 0;
            int frames = 0;
            err.println("Playing " + file + " (" + bag.lines().size() + " lines, recorded " + bag.header().started()
                    + ") as " + String.join(", ", connected.keySet()) + (rate == 1 ? "" : " at " + rate + "x") + ".");
            err.flush();
            long start = System.nanoTime();
            Unconfirmed unconfirmed = null;
            for (int round = 0; round < loops; round++) {
                for (Bag.Numbered n : bag.lines()) {
                    CliAgent through = switch (n.line()) {
                        case Bag.Signal s -> connected.get(oneAgent ? agent.as : s.agent());
                        case Bag.Removal r -> connected.get(oneAgent ? agent.as : r.agent());
                        case Bag.FrameChange f -> null;
                        case Bag.Header h -> null;
                    };
                    if (unconfirmed != null && through != null && through != unconfirmed.agent()) {
                        unconfirmed.await(); // before waiting for this line's time, so the round trip overlaps it
                        unconfirmed = null;
                    }
                    long due = Math.round((round * span + Bag.time(n.line())) * 1e6 / rate);
                    long left;
                    while ((left = due - (System.nanoTime() - start)) > 0) {
                        TimeUnit.NANOSECONDS.sleep(Math.min(left, TimeUnit.MILLISECONDS.toNanos(200)));
                        Optional<CliAgent> lost = connected.values().stream().filter(a -> a.stopped().isPresent())
                                .findFirst();
                        if (lost.isPresent()) {
                            err.println("kicnp agent play: " + lost.get().stopped().get().getMessage());
                            return 1;
                        }
                    }
                    switch (n.line()) {
                        case Bag.Signal s -> {
                            Value[] values = s.values().toArray(Value[]::new);
                            if (s.ttlMs().isPresent()) {
                                through.sensor(s.sensor(), Duration.ofMillis(scaled(s.ttlMs().get())), values);
                            } else {
                                through.sensor(s.sensor(), values);
                            }
                            unconfirmed = new Unconfirmed(through, s.sensor());
                            signals++;
                        }
                        case Bag.Removal r -> {
                            withdraw(through, r.sensor()); // a request: answered once the server has done it
                            unconfirmed = null;
                            removals++;
                        }
                        case Bag.FrameChange f -> frames++;
                        case Bag.Header h -> { }
                    }
                }
            }
            double took = (System.nanoTime() - start) / 1e9;
            spec.commandLine().getOut().println("Played " + signals + " signal" + (signals == 1 ? "" : "s") + " and "
                    + removals + " removal" + (removals == 1 ? "" : "s") + " as " + connected.size() + " agent"
                    + (connected.size() == 1 ? "" : "s") + " (" + String.join(", ", connected.keySet()) + ") in "
                    + String.format(java.util.Locale.ROOT, "%.1f", took) + " s"
                    + (loops == 1 ? "" : " (" + loops + " rounds)")
                    + (frames == 0 ? "" : "; " + frames + " frame line" + (frames == 1 ? "" : "s") + " not sent")
                    + ".");
            return 0;
        }

        /**
         * The last signal sent, which the server has not been seen to take yet. A signal is sent without an answer, and
         * each agent sends on a connection of its own, which the server may read on another of its threads: a line of
         * another agent sent right after it (two lines of one millisecond) could be taken first. So before such a
         * line, play asks the server, on the signal's own connection, for the time of the signal it keeps; the server
         * answers a connection's messages in order, so the answer comes once the signal is taken.
         */
        private record Unconfirmed(CliAgent agent, String sensor) {
            void await() {
                try {
                    agent.ask("signal_" + agent.name() + "_" + sensor, "time");
                } catch (RequestRefusedException e) {
                    if (e.code() != ErrorCode.UNKNOWN_FRAME) { // taken, and gone again by its time to live
                        throw e;
                    }
                }
            }
        }

        /**
         * A time to live scaled as the spacing is, so that a reading renewed in its time to live when recorded is
         * renewed in it when played, and one that expired expires at its recorded place.
         */
        private long scaled(long ttlMs) {
            return Math.clamp(Math.round(ttlMs / rate), 1, Message.SensorSignal.MAX_TTL_MS);
        }

        /**
         * Ends an agent's signal: the protocol has no message to withdraw a reading, so the agent destroys the
         * instance the server keeps for it (with what was derived from it). One already gone — it expired by its
         * own time to live, as it did when it was recorded — is fine.
         */
        private static void withdraw(CliAgent a, String sensor) {
            try {
                a.destroy("signal_" + a.name() + "_" + sensor);
            } catch (RequestRefusedException e) {
                if (e.code() != ErrorCode.UNKNOWN_FRAME) {
                    throw e;
                }
            }
        }
    }
}
