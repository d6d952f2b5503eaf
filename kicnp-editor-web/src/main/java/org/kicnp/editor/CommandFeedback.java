package org.kicnp.editor;

import static java.util.Objects.requireNonNull;

import java.time.Instant;

/**
 * What became of a command: started, ended (with its result) or failed (with the reason). Pushed to the page as a
 * {@code feedback} event and kept with the command in {@code GET /api/commands}.
 *
 * @param detail the result of an ended command or the reason of a failed one; empty for {@code STARTED}
 */
public record CommandFeedback(Instant at, String commandId, String robot, String action, Status status,
        String detail) {
    /** The fate of a command. */
    public enum Status {
        STARTED, ENDED, FAILED
    }

    public CommandFeedback {
        requireNonNull(at, "at");
        requireNonNull(commandId, "commandId");
        requireNonNull(robot, "robot");
        requireNonNull(action, "action");
        requireNonNull(status, "status");
        requireNonNull(detail, "detail");
    }
}
