package org.kicnp.robots;

/** Base of the unchecked exceptions of this module: something went wrong with the simulator or a robot. */
public class SimulatorException extends RuntimeException {
    public SimulatorException(String message) {
        super(message);
    }

    public SimulatorException(String message, Throwable cause) {
        super(message, cause);
    }
}
