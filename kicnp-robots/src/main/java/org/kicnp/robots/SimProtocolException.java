package org.kicnp.robots;

/** A line from the simulator that is not a valid event of {@code kicnp-sim/1}; the message quotes the line. */
public final class SimProtocolException extends SimulatorException {
    public SimProtocolException(String message) {
        super(message);
    }
}
