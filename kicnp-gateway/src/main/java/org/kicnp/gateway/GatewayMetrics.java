package org.kicnp.gateway;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;

/**
 * Counters a gateway keeps, so overload is visible rather than silent. Thread-safe. The per-message counters are
 * {@link LongAdder}s: every event loop counts every message, and one shared atomic would be a contended cache line.
 */
public final class GatewayMetrics {
    final AtomicLong connections = new AtomicLong();
    final LongAdder received = new LongAdder();
    final LongAdder sent = new LongAdder();
    final AtomicLong shed = new AtomicLong();
    final AtomicLong slowConsumersDropped = new AtomicLong();
    final AtomicLong protocolErrors = new AtomicLong();

    /** Connections accepted since start. */
    public long connections() {
        return connections.get();
    }

    /** Messages decoded from agents. */
    public long received() {
        return received.sum();
    }

    /** Messages handed to connections for writing. */
    public long sent() {
        return sent.sum();
    }

    /** Messages not sent because the receiving connection was above its write-buffer high mark. */
    public long shed() {
        return shed.get();
    }

    /** Connections closed because they kept not reading. */
    public long slowConsumersDropped() {
        return slowConsumersDropped.get();
    }

    /** Connections closed for breaking the protocol (bad frames, bad JSON, unknown types, no authentication). */
    public long protocolErrors() {
        return protocolErrors.get();
    }

    @Override public String toString() {
        return "GatewayMetrics[connections=" + connections() + ", received=" + received() + ", sent=" + sent()
                + ", shed=" + shed() + ", slowConsumersDropped=" + slowConsumersDropped()
                + ", protocolErrors=" + protocolErrors() + "]";
    }
}
