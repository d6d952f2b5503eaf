package org.kicnp.cli.platform;

import static java.util.Objects.requireNonNull;

import java.util.Map;

/**
 * One thing that happened on the platform, as written to the event log: when (epoch ms and a monotonic nano
 * time, for latencies), what kind ({@code stimulus}, {@code fired}, {@code command}, {@code feedback},
 * {@code utterance}, {@code signal}, {@code retracted}, {@code script_failed}, {@code action}) and its fields.
 */
public record PlatformEvent(long epochMillis, long nanos, String kind, Map<String, Object> fields) {
    public PlatformEvent {
        requireNonNull(kind, "kind");
        fields = Map.copyOf(fields);
    }

    static PlatformEvent now(String kind, Map<String, Object> fields) {
        return new PlatformEvent(System.currentTimeMillis(), System.nanoTime(), kind, fields);
    }

    /** A field as text, or the empty string. */
    public String text(String field) {
        Object v = fields.get(field);
        return v == null ? "" : v.toString();
    }
}
