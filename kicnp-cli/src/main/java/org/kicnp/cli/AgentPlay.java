package org.kicnp.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.concurrent.TimeUnit;
import org.kicnp.agent.RequestRefusedException;
import org.kicnp.cli.AgentCommand.CliAgent;
import org.kicnp.cli.AgentCommand.Hooks;
import org.kicnp.cli.AgentCommand.Subcommand;
import org.kicnp.core.Value;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Message;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;

/**
 * {@code kicnp agent play}: a recording of {@link AgentBag} ({@code agent record}) sent again, with the recorded
 * spacing, to a server whose rules may have changed — in the manner of {@code rosbag play}.
 */
@Command(name = "play", mixinStandardHelpOptions = true,
        description = "Send the signals of a recording (agent record) again, with the recorded spacing: each as "
                + "the agent that sent it (its token from the agent file; with --as NAME, all as NAME), with its "
                + "time to live (scaled by --rate as the spacing is); a recorded "
                + "removal destroys that agent's signal (the protocol has no message to withdraw one), with what "
                + "was derived from it. The whole file is read first: a bad line is a usage error naming "
                + "FILE:LINE, and nothing is sent. Frames that are no signals are not sent. When play ends its "
                + "agents disconnect, so the server retracts the signals they left. Prints a summary line.")
final class AgentPlay extends Subcommand {

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
