package org.kicnp.script;

import java.util.OptionalInt;

/**
 * A script threw: a JavaScript error (including a denied host access), or an exception thrown by a host function
 * it called, which is then the {@linkplain #getCause() cause}. The message names the frame and slot and quotes
 * the JavaScript message and line.
 */
public final class ScriptFailedException extends ScriptException {
    private final String scriptMessage;
    private final int line;

    public ScriptFailedException(ScriptId id, String scriptMessage, OptionalInt line, Throwable cause) {
        super(id, id.describe() + " failed" + line.stream().mapToObj(l -> " at line " + l).findFirst().orElse("")
                + ": " + scriptMessage, cause);
        this.scriptMessage = scriptMessage;
        this.line = line.orElse(0);
    }

    /** The error message as JavaScript reported it, for example {@code TypeError: x is not a function}. */
    public String scriptMessage() {
        return scriptMessage;
    }

    /** The 1-based line within the script where the error was raised, when known. */
    public OptionalInt line() {
        return line > 0 ? OptionalInt.of(line) : OptionalInt.empty();
    }
}
