package org.kicnp.cli;

import static org.kicnp.cli.AgentCommand.requirePositive;

import java.io.PrintWriter;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.kicnp.cli.AgentCommand.CliAgent;
import org.kicnp.cli.AgentCommand.Hooks;
import org.kicnp.cli.AgentCommand.Subcommand;
import org.kicnp.core.Value;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.ValueJson;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;

/** {@code kicnp agent sensor}: a sensor signal from the shell, as {@code rostopic pub} publishes a message. */
final class AgentSensor {
    private AgentSensor() {
    }

    @Command(name = "sensor", mixinStandardHelpOptions = true,
            description = "Send a sensor signal, as a robot's agent does (in the manner of rostopic pub): the server "
                    + "keeps it as the instance signal_AGENT_SENSOR of SensorSignal, which slot conditions can test. "
                    + "The server retracts an agent's signals when it disconnects, so this stays connected until "
                    + "interrupted or --for seconds; with --rate it repeats the signal. Each VALUE is read as true or "
                    + "false, a whole number, a decimal number, @NAME (a reference to frame NAME), a JSON array (a "
                    + "list: [0.1, 0.2, {\"ref\": \"userA\"}]), or else text (\"quoted\" text is always text).")
    static final class Sensor extends Subcommand {

        @Parameters(index = "0", paramLabel = "SENSOR", description = "The sensor's name.")
        String sensor;

        @Parameters(index = "1..*", arity = "0..*", paramLabel = "VALUE", description = "The signal's values.")
        List<String> values = List.of();

        @Option(names = "--ttl", paramLabel = "MS",
                description = "Time to live in milliseconds (1 to 86400000): the server retracts the reading, with "
                        + "what was derived from it, unless a newer one comes by then.")
        Long ttlMs;

        @Option(names = "--rate", paramLabel = "HZ", description = "Send the signal this many times a second.")
        Double rate;

        @Option(names = "--for", paramLabel = "SECONDS", description = "Disconnect after this many seconds.")
        Double seconds;

        @Override public Integer call() throws InterruptedException {
            if (!Message.NAME.matcher(sensor).matches()) {
                throw new ParameterException(spec.commandLine(), "SENSOR '" + sensor + "' is not a sensor name: use "
                        + "letters, digits, '_' and '-', starting with a letter or '_'.");
            }
            if (seconds != null) {
                requirePositive(spec, "--for", seconds);
            }
            if (rate != null && (!(rate > 0) || rate > 1000)) {
                throw new ParameterException(spec.commandLine(), "--rate must be above 0 and at most 1000 a second, not "
                        + rate + ".");
            }
            if (ttlMs != null && (ttlMs < 1 || ttlMs > Message.SensorSignal.MAX_TTL_MS)) {
                throw new ParameterException(spec.commandLine(), "--ttl must be 1 to "
                        + Message.SensorSignal.MAX_TTL_MS + " milliseconds, not " + ttlMs + ".");
            }
            Value[] read;
            try {
                read = values.stream().map(Sensor::value).toArray(Value[]::new);
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage());
            }
            // Times as nanoseconds since the start: how long to run (until interrupted: no end) and between sends
            // (without --rate: one send).
            long length = seconds == null ? Long.MAX_VALUE : Math.round(seconds * 1e9);
            long period = rate == null ? 0 : Math.round(1e9 / rate);
            PrintWriter err = spec.commandLine().getErr();
            try (CliAgent a = connect(Hooks.NONE)) {
                long start = System.nanoTime();
                for (long sent = 1; ; sent++) {
                    if (ttlMs == null) {
                        a.sensor(sensor, read);
                    } else {
                        a.sensor(sensor, Duration.ofMillis(ttlMs), read);
                    }
                    if (sent == 1) {
                        err.println("Sent signal_" + a.name() + "_" + sensor + (rate == null ? "" : " " + rate
                                + " times a second") + "; " + (seconds == null ? "interrupt to stop"
                                : "stopping in " + seconds + " s") + " (the server retracts it then).");
                        err.flush();
                    }
                    long due = period == 0 ? length : Math.min(length, sent * period);
                    long left;
                    while ((left = due - (System.nanoTime() - start)) > 0) {
                        TimeUnit.NANOSECONDS.sleep(Math.min(left, TimeUnit.SECONDS.toNanos(1)));
                        if (a.stopped().isPresent()) {
                            err.println("kicnp agent sensor: " + a.stopped().get().getMessage());
                            return 1;
                        }
                    }
                    if (System.nanoTime() - start >= length) {
                        return 0;
                    }
                }
            }
        }

        /** A VALUE argument as a slot value. */
        static Value value(String text) {
            if (text.startsWith("[")) {
                com.fasterxml.jackson.databind.JsonNode list;
                try {
                    list = new com.fasterxml.jackson.databind.ObjectMapper().readTree(text);
                } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
                    throw new IllegalArgumentException("VALUE '" + text + "' starts a list but is not a JSON array: "
                            + e.getOriginalMessage());
                }
                return ValueJson.fromJson(list, n -> new IllegalArgumentException("VALUE '"
                        + text + "' holds " + n + ", which is no slot value: items are numbers, true or false, "
                        + "\"text\", {\"ref\": \"NAME\"} or lists."));
            }
            if (text.length() >= 2 && text.startsWith("\"") && text.endsWith("\"")) {
                return Value.of(text.substring(1, text.length() - 1));
            }
            if (text.equals("true") || text.equals("false")) {
                return Value.of(Boolean.parseBoolean(text));
            }
            if (text.matches("[+-]?\\d{1,18}")) {
                return Value.of(Long.parseLong(text));
            }
            if (text.matches("[+-]?(\\d+\\.\\d*|\\.\\d+|\\d+)([eE][+-]?\\d+)?")) {
                double d = Double.parseDouble(text);
                if (Double.isFinite(d)) {
                    return Value.of(d);
                }
            }
            if (text.length() > 1 && text.startsWith("@")) {
                return Value.ref(text.substring(1));
            }
            return Value.of(text);
        }
    }
}
