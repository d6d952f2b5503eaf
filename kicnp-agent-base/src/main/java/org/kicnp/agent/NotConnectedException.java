package org.kicnp.agent;

/** The agent has no registered connection right now (it is connecting, reconnecting or closed). */
public final class NotConnectedException extends AgentException {
    public NotConnectedException(String message) {
        super(message);
    }

    /** @param cause the failure of the connection that was in use (say, the socket closed under a write) */
    public NotConnectedException(String message, Throwable cause) {
        super(message, cause);
    }
}
