package org.kicnp.script;

import static java.util.Objects.requireNonNull;

/**
 * Where a script comes from: the frame and the slot that hold its text. Every error a script causes names it,
 * so a knowledge engineer can find the script to fix.
 *
 * @param frame the name of the frame holding the script, for example {@code Greeting}
 * @param slot the name of the slot holding the script, for example {@code onInstantiate}
 */
public record ScriptId(String frame, String slot) {

    public ScriptId {
        requireNonNull(frame, "frame");
        requireNonNull(slot, "slot");
    }

    /** The phrase used at the start of error messages: {@code Script in slot 'onInstantiate' of frame 'Greeting'}. */
    public String describe() {
        return "Script in slot '" + slot + "' of frame '" + frame + "'";
    }

    /** A short name, {@code Greeting.onInstantiate}, used as the source name in JavaScript stack traces. */
    public String sourceName() {
        return frame + "." + slot;
    }

    @Override public String toString() {
        return sourceName();
    }
}
