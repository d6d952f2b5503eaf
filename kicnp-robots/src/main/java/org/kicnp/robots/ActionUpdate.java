package org.kicnp.robots;

import com.fasterxml.jackson.databind.JsonNode;

import java.util.Objects;
import java.util.Optional;

/**
 * What happens to one simulator command, in order: {@link Started}, any number of {@link Progress}, then exactly one
 * of {@link Ended} or {@link Failed}. A command the simulator refused, one that got no ack in time, and one cut
 * short by the simulator's death also end in {@link Failed}, with a reason that says so; so an observer always sees
 * a terminal update.
 */
public sealed interface ActionUpdate {

    /** The action started; {@code args} has the simulator's defaults filled in. */
    record Started(double t, JsonNode args) implements ActionUpdate {
        public Started {
            Objects.requireNonNull(args, "args");
        }
    }

    /** Periodic progress: {@code fraction} for timed actions, the whole event for motion fields. */
    record Progress(double t, Optional<Double> fraction, JsonNode body) implements ActionUpdate {
        public Progress {
            Objects.requireNonNull(fraction, "fraction");
            Objects.requireNonNull(body, "body");
        }
    }

    /** The action ended well; {@code result} is action-specific (see PROTOCOL.md). */
    record Ended(double t, JsonNode result) implements ActionUpdate {
        public Ended {
            Objects.requireNonNull(result, "result");
        }
    }

    /** The action failed, was refused or was cut short; {@code reason} is a sentence fragment for people. */
    record Failed(double t, String reason) implements ActionUpdate {
        public Failed {
            Objects.requireNonNull(reason, "reason");
        }
    }

    /** Whether this is the last update of its action. */
    default boolean terminal() {
        return this instanceof Ended || this instanceof Failed;
    }
}
