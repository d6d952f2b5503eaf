package org.kicnp.protocol;

/** The stages of a command's life reported by the robot (section 3.3: robots "send back responses"). */
public enum FeedbackStage {
    STARTED,
    PROGRESS,
    ENDED,
    FAILED;

    /** Whether this stage ends the command: after it no more feedback is expected. */
    public boolean terminal() {
        return this == ENDED || this == FAILED;
    }
}
