package org.kicnp.gateway;

import org.kicnp.protocol.Message.Command;

/**
 * Hears how the platform's commands go: started, progress, then exactly one of ended or failed. The inference
 * engine implements it to confirm "the feedback of robot actions". Called on a gateway I/O thread: return quickly.
 */
public interface FeedbackListener {
    /** A listener that ignores everything, for a gateway with no inference engine. */
    FeedbackListener NONE = new FeedbackListener() {
        @Override public void ended(Command command, String result) {
        }

        @Override public void failed(Command command, String reason) {
        }
    };

    default void started(Command command) {
    }

    /** Progress, with the fraction done when the robot knows it (else {@code NaN}) and a note. */
    default void progress(Command command, double fraction, String note) {
    }

    void ended(Command command, String result);

    /** The command failed: the robot said so, the robot is not connected, or it disconnected. */
    void failed(Command command, String reason);
}
