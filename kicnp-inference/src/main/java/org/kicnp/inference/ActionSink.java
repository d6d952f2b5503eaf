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
}
