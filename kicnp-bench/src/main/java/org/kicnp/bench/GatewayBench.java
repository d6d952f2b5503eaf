package org.kicnp.bench;

import java.util.List;
import java.util.Locale;

/**
 * {@code ./kicnp bench gateway-pingpong}: round-trip latency and rate of K-ICNP's gateway and agent SDK, side by side with
 * Mosquitto, the common MQTT broker, on the same machine over loopback. Both run the same ping-pong: two clients,
 * each hop an acknowledged send through the hub (K-ICNP relay with its ack; MQTT QoS 1 publish with its PUBACK).
 */
public final class GatewayBench {
    private GatewayBench() {
    }

    /**
     * Runs both peers, one after the other.
     *
     * @param roundTrips measured round trips per peer
     * @param payloadBytes the size of each message body
     */
    public static List<PingPongResult> run(int roundTrips, int payloadBytes) throws Exception {
        if (roundTrips < 1 || payloadBytes < 0) {
            throw new IllegalArgumentException("Need at least one round trip and a payload of 0 bytes or more, not "
                    + roundTrips + " and " + payloadBytes + ".");
        }
        int warmup = Math.min(roundTrips, 2_000);
        return List.of(KicnpPingPong.run(roundTrips, warmup, payloadBytes),
                MosquittoPingPong.run(roundTrips, warmup, payloadBytes));
    }

    /** The results as a text table, one line per peer, for the CLI to print. */
    public static String table(List<PingPongResult> results) {
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "%-24s %11s %8s %9s %9s %9s %14s%n",
                "peer", "round trips", "payload", "p50 µs", "p99 µs", "max µs", "round trips/s"));
        for (PingPongResult r : results) {
            if (r.measured()) {
                sb.append(String.format(Locale.ROOT, "%-24s %11d %8d %9d %9d %9d %14.0f%n", r.peer(), r.roundTrips(),
                        r.payloadBytes(), r.p50Micros(), r.p99Micros(), r.maxMicros(), r.roundTripsPerSecond()));
            } else {
                sb.append(String.format(Locale.ROOT, "%-24s %s%n", r.peer(), r.note().orElseThrow()));
            }
        }
        return sb.toString();
    }
}
