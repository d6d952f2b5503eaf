package org.kicnp.core;

import static java.util.Objects.requireNonNull;

import java.util.Optional;

/** One thing wrong with a batch: the frame (and slot, where one is at fault) and a sentence saying what. */
public record Problem(String frame, Optional<String> slot, String message) {
    public Problem {
        requireNonNull(frame, "frame");
        requireNonNull(slot, "slot");
        requireNonNull(message, "message");
    }

    static Problem of(String frame, String message) {
        return new Problem(frame, Optional.empty(), message);
    }

    static Problem of(String frame, String slot, String message) {
        return new Problem(frame, Optional.of(slot), message);
    }

    @Override public String toString() {
        return message;
    }
}
