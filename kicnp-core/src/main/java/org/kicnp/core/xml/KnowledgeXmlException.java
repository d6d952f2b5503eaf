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
    private final List<SourcedFrame> framesRead;

    public KnowledgeXmlException(List<LoadError> errors) {
        this(errors, List.of());
    }

    /**
     * @param framesRead the frames that were read and mapped without an error of their own, for checks a caller
     *     makes besides the loader's (such as {@code validate}'s script syntax check), so it can report in one round
     */
    public KnowledgeXmlException(List<LoadError> errors, List<SourcedFrame> framesRead) {
        super(errors.stream().map(LoadError::format).collect(Collectors.joining("\n")));
        if (errors.isEmpty()) {
            throw new IllegalArgumentException("A KnowledgeXmlException needs at least one error.");
        }
        this.errors = List.copyOf(errors);
        this.framesRead = List.copyOf(framesRead);
    }

    static KnowledgeXmlException of(SourceLocation where, String message) {
        return new KnowledgeXmlException(List.of(LoadError.at(where, message)));
    }

    /** Every error, in the order found (file by file, top to bottom, then the knowledge base's checks). */
    public List<LoadError> errors() {
        return errors;
    }

    /**
     * The frames of the failed load that were read and mapped without an error in their XML, in file order (they
     * may still have problems against the frame model); empty when the error was not in reading frames.
     */
    public List<SourcedFrame> framesRead() {
        return framesRead;
    }
}
