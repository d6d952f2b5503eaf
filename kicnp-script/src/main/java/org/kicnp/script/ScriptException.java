package org.kicnp.script;

import static java.util.Objects.requireNonNull;

/** Base of every unchecked exception thrown by the script runtime; it always names the script that caused it. */
public class ScriptException extends RuntimeException {
    private final ScriptId id;

    public ScriptException(ScriptId id, String message) {
        super(message);
        this.id = requireNonNull(id, "id");
    }

    public ScriptException(ScriptId id, String message, Throwable cause) {
        super(message, cause);
        this.id = requireNonNull(id, "id");
    }

    /** The frame and slot of the script that failed. */
    public ScriptId id() {
        return id;
    }
}
