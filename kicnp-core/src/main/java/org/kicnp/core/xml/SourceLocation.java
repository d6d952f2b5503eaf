package org.kicnp.core.xml;

import static java.util.Objects.requireNonNull;

/**
 * A place in a knowledge file: the source (the file path as it was given, or a name such as {@code editor}) and the
 * 1-based line and column of an element's start tag.
 */
public record SourceLocation(String source, int line, int column) {
    public SourceLocation {
        requireNonNull(source, "source");
    }

    /** {@code source:line:column}, the form compilers and editors understand. */
    @Override public String toString() {
        return source + ":" + line + ":" + column;
    }
}
