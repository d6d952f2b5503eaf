package org.kicnp.core.xml;

import static java.util.Objects.requireNonNull;

import java.util.Optional;
import org.kicnp.core.Problem;

/**
 * One thing wrong with a knowledge file: where it is, a sentence saying what, and the frame (and slot, where one is
 * at fault) it concerns, when the error is about one, so that a tool such as the editor can point at it.
 */
public record LoadError(String source, int line, int column, String message, Optional<String> frame,
        Optional<String> slot) {
    public LoadError {
        requireNonNull(source, "source");
        requireNonNull(message, "message");
        requireNonNull(frame, "frame");
        requireNonNull(slot, "slot");
    }

    /** An error about no particular frame, such as a file that cannot be read or XML that is not well-formed. */
    public LoadError(String source, int line, int column, String message) {
        this(source, line, column, message, Optional.empty(), Optional.empty());
    }

    static LoadError at(SourceLocation where, String message) {
        return new LoadError(where.source(), where.line(), where.column(), message);
    }

    /** An error about frame {@code frame} (null: none) and, when not null, its slot {@code slot}. */
    static LoadError at(SourceLocation where, String message, String frame, String slot) {
        return new LoadError(where.source(), where.line(), where.column(), message, Optional.ofNullable(frame),
                Optional.ofNullable(slot));
    }

    /** A problem the knowledge base's checks found, placed at {@code where}. */
    static LoadError at(SourceLocation where, Problem p) {
        return new LoadError(where.source(), where.line(), where.column(), p.message(),
                Optional.of(p.frame()).filter(f -> !f.isEmpty()), p.slot());
    }

    public SourceLocation location() {
        return new SourceLocation(source, line, column);
    }

    /** {@code source:line:column: message}. */
    public String format() {
        return source + ":" + line + ":" + column + ": " + message;
    }
}
