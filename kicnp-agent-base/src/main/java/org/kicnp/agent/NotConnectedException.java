package org.kicnp.agent;

/** The agent has no registered connection right now (it is connecting, reconnecting or closed). */
public final class NotConnectedException extends AgentException {
    public NotConnectedException(String message) {
        super(message);
    }
}
