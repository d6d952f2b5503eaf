package org.kicnp.inference;

/**
 * The life-cycle reports the gateway gives the engine about actions it was sent. Safe to call from any thread: the
 * report is queued and takes effect on the engine thread at its next run.
 */
public interface ActionFeedback {
    void actionStarted(String actionId);

    void actionEnded(String actionId, String result);

    void actionFailed(String actionId, String reason);
}
