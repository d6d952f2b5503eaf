package org.kicnp.editor;

/** Base of the editor's unchecked exceptions. Messages are whole sentences that quote names. */
public class EditorException extends RuntimeException {
    public EditorException(String message) {
        super(message);
    }

    public EditorException(String message, Throwable cause) {
        super(message, cause);
    }
}
