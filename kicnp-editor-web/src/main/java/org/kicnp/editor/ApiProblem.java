package org.kicnp.editor;

import static java.util.Objects.requireNonNull;

import org.kicnp.core.Problem;

/**
 * One problem reported to the browser: the frame and slot at fault (empty text when none), a sentence, and for
 * XML imports the line and column (0 when unknown). The JSON shape of every 422 answer's {@code problems} list.
 */
record ApiProblem(String frame, String slot, String message, int line, int column) {
    ApiProblem {
        requireNonNull(frame, "frame");
        requireNonNull(slot, "slot");
        requireNonNull(message, "message");
    }

    static ApiProblem of(Problem p) {
        return new ApiProblem(p.frame(), p.slot().orElse(""), p.message(), 0, 0);
    }

    static ApiProblem of(String frame, String slot, String message) {
        return new ApiProblem(frame, slot, message, 0, 0);
    }
}
