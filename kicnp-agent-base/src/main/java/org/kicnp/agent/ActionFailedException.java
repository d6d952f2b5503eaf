package org.kicnp.agent;

/** A command ended with {@code failed}; the message is the robot's (or the server's) reason. */
public final class ActionFailedException extends AgentException {
    public ActionFailedException(String message) {
        super(message);
    }
}
