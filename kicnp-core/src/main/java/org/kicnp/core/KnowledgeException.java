package org.kicnp.core;

/** Base of every unchecked exception thrown by the knowledge core. Messages are whole sentences that quote names. */
public class KnowledgeException extends RuntimeException {
    public KnowledgeException(String message) {
        super(message);
    }

    public KnowledgeException(String message, Throwable cause) {
        super(message, cause);
    }
}
