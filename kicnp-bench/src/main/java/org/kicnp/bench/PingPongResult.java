package org.kicnp.bench;

import static java.util.Objects.requireNonNull;

import java.util.Optional;
import org.HdrHistogram.Histogram;

/**
 * One peer's ping-pong numbers: round-trip latency percentiles in microseconds and round trips per second, or why
 * the peer could not be measured.
 */
public record PingPongResult(String peer, int roundTrips, int payloadBytes, long p50Micros, long p99Micros,
                             long maxMicros, double roundTripsPerSecond, Optional<String> note) {
    public PingPongResult {
        requireNonNull(peer, "peer");
        requireNonNull(note, "note");
    }

    static PingPongResult of(String peer, int payloadBytes, Histogram h, long elapsedNanos) {
        int n = (int) h.getTotalCount();
        return new PingPongResult(peer, n, payloadBytes, h.getValueAtPercentile(50), h.getValueAtPercentile(99),
                h.getMaxValue(), n / (elapsedNanos / 1e9), Optional.empty());
    }

    static PingPongResult skipped(String peer, int payloadBytes, String why) {
        return new PingPongResult(peer, 0, payloadBytes, 0, 0, 0, 0, Optional.of(why));
    }

    /** Whether the peer was measured. */
    public boolean measured() {
        return note.isEmpty();
    }
}
