package org.kicnp.core;

/** A frame or slot breaks a rule of the frame model, on its own or against the knowledge base. */
public class InvalidFrameException extends KnowledgeException {
    public InvalidFrameException(String message) {
        super(message);
    }
}
