package org.kicnp.editor;

import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Port: tele-operation (paper section 3.2), a person commanding a robot by hand from the World panel, and the
 * person's judgement that an action was wrong (section 3.3: "based on the user's judgment on the actions of
 * robots, K-ICNP can adjust its control instructions or generate new tasks").
 */
public interface TeleOperation {
    /** The connected robots and the actions each can perform ({@code GET /api/robots}). */
    List<RobotCapabilities> robots();

    /**
     * Sends one command to {@code robot} ({@code POST /api/robots/{robot}/commands}) and answers its command id,
     * the id its {@link CommandFeedback} carries. Returns once the command is on its way, not when it ends.
     *
     * @throws IllegalArgumentException unknown robot or action, a missing or malformed argument (422, message shown)
     * @throws IllegalStateException the robot is not connected or cannot take commands now (503)
     */
    String send(String robot, String action, Map<String, String> args);

    /**
     * Records the person's judgement that the action with this id (a tele-operated command or an action the
     * platform issued) was wrong, with their reason ({@code POST /api/actions/{id}/wrong}). The platform asserts a
     * {@code WrongAction} instance behavior frames can match (see docs/editor.md).
     *
     * @throws IllegalArgumentException no action with this id is known (422)
     */
    void markWrong(String actionId, String reason);

    /**
     * Asks for the action with this id (a tele-operated command or an action the platform issued) to be stopped
     * ({@code POST /api/actions/{id}/stop}), as a ROS action client preempts a goal: the action fails as cancelled
     * with {@code reason}, and a robot already performing it halts. Its feedback follows as for any command. Returns
     * once the request is on its way.
     *
     * @throws IllegalArgumentException no action with this id is known, or it is not running any more (422)
     */
    void stop(String actionId, String reason);

    /** Calls {@code listener} with feedback on every command (tele-operated or not), from any thread. */
    Subscription onFeedback(Consumer<CommandFeedback> listener);
}
