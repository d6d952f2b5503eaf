package org.kicnp.cli;

import static org.kicnp.cli.AgentCommand.requirePositive;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
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
 * {@code kicnp agent record}: the robots' sensor stream written to a file (a {@link Bag}) as the server receives it,
 * in the manner of {@code rosbag record}; {@link AgentPlay} ({@code agent play}) sends it again later.
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
            Map<String, Read> byName = new TreeMap<>();
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
                    byName.put(f.name(), new Read(f, at));
                }
            }
            List<Bag.Signal> present = new ArrayList<>();
            for (Read read : byName.values()) {
                Frame f = read.frame();
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
                values.flatMap(v -> Signals.present(f, v, read.at())).ifPresent(present::add);
            }
            return present;
        }

        /** A frame as a query answered it, and the server's clock (epoch ms) when it read it. */
        private record Read(Frame frame, long at) {
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
}
