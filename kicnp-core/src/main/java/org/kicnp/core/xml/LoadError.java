package org.kicnp.core.xml;

import static java.util.Objects.requireNonNull;

/** One thing wrong with a knowledge file: where it is and a sentence saying what. */
public record LoadError(String source, int line, int column, String message) {
    public LoadError {
        requireNonNull(source, "source");
        requireNonNull(message, "message");
    }

    static LoadError at(SourceLocation where, String message) {
        return new LoadError(where.source(), where.line(), where.column(), message);
    }

    public SourceLocation location() {
        return new SourceLocation(source, line, column);
    }

    /** {@code source:line:column: message}. */
    public String format() {
        return source + ":" + line + ":" + column + ": " + message;
    }
}
