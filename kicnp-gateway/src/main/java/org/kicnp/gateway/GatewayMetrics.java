package org.kicnp.gateway;

import java.util.concurrent.atomic.AtomicLong;

/** Counters a gateway keeps, so overload is visible rather than silent. Thread-safe. */
public final class GatewayMetrics {
    final AtomicLong connections = new AtomicLong();
    final AtomicLong received = new AtomicLong();
    final AtomicLong sent = new AtomicLong();
    final AtomicLong shed = new AtomicLong();
    final AtomicLong slowConsumersDropped = new AtomicLong();
    final AtomicLong protocolErrors = new AtomicLong();

    /** Connections accepted since start. */
    public long connections() {
        return connections.get();
    }

    /** Messages decoded from agents. */
    public long received() {
        return received.get();
    }

    /** Messages handed to connections for writing. */
    public long sent() {
        return sent.get();
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
