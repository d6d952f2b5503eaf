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
     * @throws IllegalArgumentException when a command with the same id is already in flight on that robot, or when
     *     the frame its feedback would go to holds another action's (docs/protocol.md, "Commands and feedback")
     */
    void send(Command command);

    /**
     * Asks the robot to stop a command in flight; its answer is the command's last feedback ({@code failed}, with a
     * reason that starts with "cancelled" — or "cancel failed" when the robot's agent could not stop it — or
     * {@code ended} if it finished first). Never blocks on the network.
     *
     * @return false when no such command is in flight (it ended already, or was never sent)
     */
    default boolean cancel(String robot, String commandId, String reason) {
        return false;
    }
}
