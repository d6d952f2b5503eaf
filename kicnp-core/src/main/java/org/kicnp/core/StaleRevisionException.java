package org.kicnp.core;

/** A replace or removal expected a frame revision that is no longer current: someone else saved the frame in between. */
public final class StaleRevisionException extends KnowledgeException {
    private final String frame;
    private final long expected;
    private final long actual;

    StaleRevisionException(String frame, long expected, long actual) {
        super("Frame '" + frame + "' was changed by someone else (revision " + actual + ", you edited revision "
                + expected + "); reload it and apply your edit again.");
        this.frame = frame;
        this.expected = expected;
        this.actual = actual;
    }

    public String frame() {
        return frame;
    }

    public long expected() {
        return expected;
    }

    public long actual() {
        return actual;
    }
}
