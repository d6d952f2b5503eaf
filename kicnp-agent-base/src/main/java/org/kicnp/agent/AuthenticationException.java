package org.kicnp.agent;

/** The server refused the agent's name, token or kind. Not retried: the configuration must change. */
public final class AuthenticationException extends AgentException {
    public AuthenticationException(String message) {
        super(message);
    }
}
