package org.kicnp.bench;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code ./kicnp bench gateway-pingpong}: the command around {@link GatewayBench}, printing its table and, as the last line,
 * one JSON object per the bench convention (a peer that could not be measured has {@code null} figures).
 */
@Command(name = "gateway-pingpong",
        mixinStandardHelpOptions = true,
        description = {
            "Gateway: round-trip latency and rate, beside Mosquitto (MQTT QoS 1).",
            "The K-ICNP gateway and agent SDK and Mosquitto run the same ping-pong over loopback;",
            "Mosquitto is skipped with a note when it is not installed.",
            "The last line of output is one JSON object with the figures."
        })
final class GatewayBenchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--round-trips", defaultValue = "20000",
            description = "Measured round trips per peer (default: ${DEFAULT-VALUE}).")
    int roundTrips;

    @Option(names = "--payload", defaultValue = "64", description = "Message body size in bytes (default: ${DEFAULT-VALUE}).")
    int payloadBytes;

    @Override public Integer call() throws Exception {
        if (roundTrips < 1 || payloadBytes < 0) {
            throw new ParameterException(spec.commandLine(), "Need --round-trips of 1 or more and --payload of 0 or more.");
        }
        PrintWriter out = spec.commandLine().getOut();
        List<PingPongResult> results = GatewayBench.run(roundTrips, payloadBytes);
        out.print(GatewayBench.table(results));
        out.println();
        out.println(json(results));
        out.flush();
        return 0;
    }

    static String json(List<PingPongResult> results) {
        StringBuilder sb = new StringBuilder("{\"round_trips\": ").append(results.get(0).roundTrips() > 0
                ? results.get(0).roundTrips() : 0).append(", \"peers\": {");
        for (int i = 0; i < results.size(); i++) {
            PingPongResult r = results.get(i);
            sb.append(i == 0 ? "" : ", ").append('"').append(key(r.peer())).append("\": ");
            if (r.measured()) {
                sb.append(String.format(Locale.ROOT, "{\"p50_us\": %d, \"p99_us\": %d, \"max_us\": %d, \"round_trips_per_s\": %.0f}",
                        r.p50Micros(), r.p99Micros(), r.maxMicros(), r.roundTripsPerSecond()));
            } else {
                sb.append("null");
            }
        }
        return sb.append("}}").toString();
    }

    /** A JSON key for a peer's name: lower case, words joined by underscores. */
    private static String key(String peer) {
        return peer.toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9]+", "_").replaceAll("^_|_$", "");
    }
}
