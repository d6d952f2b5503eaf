package org.kicnp.core;

/** A frame was asked for by name and there is none. */
public final class UnknownFrameException extends KnowledgeException {
    public UnknownFrameException(String name) {
        super("There is no frame named '" + name + "'.");
    }
}
