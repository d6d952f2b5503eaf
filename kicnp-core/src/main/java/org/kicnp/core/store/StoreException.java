package org.kicnp.core.store;

import org.kicnp.core.KnowledgeException;

/** The knowledge store could not read or write its directory, or found it damaged beyond what a crash explains. */
public class StoreException extends KnowledgeException {
    public StoreException(String message) {
        super(message);
    }

    public StoreException(String message, Throwable cause) {
        super(message, cause);
    }
}
