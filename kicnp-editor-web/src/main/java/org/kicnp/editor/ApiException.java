package org.kicnp.editor;

import java.util.List;

/**
 * A request the API refuses, with the HTTP status to answer and, for validation failures, every problem found.
 * Thrown inside the handlers and turned into a JSON error body in one place ({@link ApiHandler}).
 */
final class ApiException extends EditorException {
    private final int status;
    private final List<ApiProblem> problems;

    ApiException(int status, String message) {
        this(status, message, List.of());
    }

    ApiException(int status, String message, List<ApiProblem> problems) {
        super(message);
        this.status = status;
        this.problems = List.copyOf(problems);
    }

    static ApiException invalid(List<ApiProblem> problems) {
        String message = problems.size() == 1 ? problems.getFirst().message()
                : problems.size() + " problems; nothing was changed.";
        return new ApiException(422, message, problems);
    }

    int status() {
        return status;
    }

    List<ApiProblem> problems() {
        return problems;
    }
}
