package org.kicnp.agent;

/** The server did not answer a request, or a command did not end, in time. */
public final class AgentTimeoutException extends AgentException {
    public AgentTimeoutException(String message) {
        super(message);
    }
}
