package org.kicnp.inference;

import java.util.Map;

/**
 * The seam to the JavaScript interpreter. The engine passes the globals a script sees ({@code s}, and functions as
 * {@link HostFunction}s) and the frame and slot the script belongs to, so errors can name them. Any exception thrown
 * (a syntax error, a script error, a timeout) fails the firing that ran the script.
 */
public interface ScriptHost {
    /** A host that has no interpreter: every script fails with a message saying so. */
    ScriptHost NONE = new ScriptHost() {
        @Override public Object run(String frame, String slot, String source, Map<String, Object> globals) {
            throw new InferenceException("Slot '" + slot + "' of frame '" + frame
                    + "' holds a script, but this engine has no script runtime.");
        }

        @Override public boolean test(String frame, String slot, String source, Map<String, Object> globals) {
            return (Boolean) run(frame, slot, source, globals);
        }
    };

    /** Runs a script; returns its result as plain Java, or null when it has none. */
    Object run(String frame, String slot, String source, Map<String, Object> globals);

    /** Evaluates a script condition to true or false. */
    boolean test(String frame, String slot, String source, Map<String, Object> globals);

    /**
     * Gets a script ready ahead of its first run (parses it, for a host that parses), so that run does not pay for
     * it. Called from a background thread, possibly while scripts run; a script that does not parse is left for its
     * run to report. Does nothing by default.
     */
    default void prepare(String frame, String slot, String source) {
    }
}
