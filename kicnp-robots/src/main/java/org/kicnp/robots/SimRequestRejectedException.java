package org.kicnp.robots;

import java.util.Objects;
import java.util.Optional;

/** The simulator answered a request with an {@code error} event: it was invalid or refused, nothing started. */
public final class SimRequestRejectedException extends SimulatorException {
    private final String field;

    public SimRequestRejectedException(String message, Optional<String> field) {
        super(message);
        this.field = Objects.requireNonNull(field, "field").orElse(null);
    }

    /** The request member at fault, when the simulator named one (e.g. {@code args.x}, {@code action}). */
    public Optional<String> field() {
        return Optional.ofNullable(field);
    }
}
