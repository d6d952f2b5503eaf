package org.kicnp.inference;

/** The engine's source of time, for action timeouts; tests pass a clock they move by hand. */
@FunctionalInterface
public interface Clock {
    /** The system clock. */
    Clock SYSTEM = System::currentTimeMillis;

    long millis();
}
