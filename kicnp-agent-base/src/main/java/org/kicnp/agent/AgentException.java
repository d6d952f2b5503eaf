package org.kicnp.agent;

/** Base of the SDK's errors; each subclass is one way a call can fail. */
public class AgentException extends RuntimeException {
    public AgentException(String message) {
        super(message);
    }

    public AgentException(String message, Throwable cause) {
        super(message, cause);
    }
}
