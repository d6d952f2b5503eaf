package org.kicnp.inference;

/** Sees every step of inference, on the engine thread, as it happens. Must not block. */
@FunctionalInterface
public interface TraceListener {
    void trace(TraceEvent event);
}
