package org.kicnp.robots;

/**
 * The simulator process is gone (it exited, was killed, or its pipe broke): thrown by every call after its death
 * and used to fail every request and action that was in flight. The message says how it died.
 */
public final class SimulatorExitedException extends SimulatorException {
    public SimulatorExitedException(String message) {
        super(message);
    }
}
