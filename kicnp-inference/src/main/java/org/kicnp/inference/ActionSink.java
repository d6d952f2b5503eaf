package org.kicnp.inference;

/**
 * Where released actions go: the gateway implements this and reports back through {@link ActionFeedback}.
 * Called on the engine thread; must not block.
 */
@FunctionalInterface
public interface ActionSink {
    /** A sink that drops actions: for engines that only infer. */
    ActionSink NONE = a -> { };

    void send(Action action);

    /**
     * Asks the robot to stop an action the engine gave up on (it timed out) or that was cancelled; the engine has
     * already finished it, so what the robot answers changes nothing. Must not block. By default nothing is sent.
     */
    default void cancel(Action action, String reason) {
    }
}
