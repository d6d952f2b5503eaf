package org.kicnp.gateway;

import org.kicnp.protocol.Message.Command;

/**
 * Where the platform sends robot commands (section 3.3: "the instruction from K-ICNP will be converted to the
 * command of local control program by software agents"). The inference engine calls it; the gateway delivers the
 * command to the robot's agent. Answers come back through the {@link FeedbackListener}.
 */
@FunctionalInterface
public interface ActionSink {
    /**
     * Sends a command to the agent of {@code command.robot()}. Never blocks on the network. If the robot is not
     * connected, or goes away before the command ends, the listener hears {@code failed} with the reason.
     *
     * @throws IllegalArgumentException when a command with the same id is already in flight on that robot
     */
    void send(Command command);
}
