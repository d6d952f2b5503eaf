package org.kicnp.core.xml;

import java.util.List;
import java.util.stream.Collectors;
import org.kicnp.core.KnowledgeException;

/**
 * Knowledge files could not be read or loaded; nothing was changed. Carries every error found, each with its file,
 * line and column; the message lists them all, one per line.
 */
public final class KnowledgeXmlException extends KnowledgeException {
    private final List<LoadError> errors;

    public KnowledgeXmlException(List<LoadError> errors) {
        super(errors.stream().map(LoadError::format).collect(Collectors.joining("\n")));
        if (errors.isEmpty()) {
            throw new IllegalArgumentException("A KnowledgeXmlException needs at least one error.");
        }
        this.errors = List.copyOf(errors);
    }

    static KnowledgeXmlException of(SourceLocation where, String message) {
        return new KnowledgeXmlException(List.of(LoadError.at(where, message)));
    }

    /** Every error, in the order found (file by file, top to bottom, then the knowledge base's checks). */
    public List<LoadError> errors() {
        return errors;
    }
}
