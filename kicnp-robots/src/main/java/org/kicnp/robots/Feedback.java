package org.kicnp.robots;

import java.util.Objects;

/**
 * What a robot reports on one platform command (section 3.3, "confirming the feedback of robot actions"), in the
 * shape of the protocol's {@code feedback} stages: {@link Started}, any number of {@link Progress}, then exactly one
 * of {@link Ended} (with the result as JSON text) or {@link Failed} (with the reason).
 */
public sealed interface Feedback {

    record Started() implements Feedback { }

    /** {@code fraction} is 0..1; {@code note} is the simulator's progress fields as JSON text. */
    record Progress(double fraction, String note) implements Feedback {
        public Progress {
            Objects.requireNonNull(note, "note");
        }
    }

    /** {@code result} is the simulator's result as JSON text (a {@code say} result holds the spoken text). */
    record Ended(String result) implements Feedback {
        public Ended {
            Objects.requireNonNull(result, "result");
        }
    }

    /** {@code reason} says why, for people: the simulator's reason, a refused argument, or the simulator's death. */
    record Failed(String reason) implements Feedback {
        public Failed {
            Objects.requireNonNull(reason, "reason");
        }
    }

    /** Whether this is the last feedback of its command. */
    default boolean terminal() {
        return this instanceof Ended || this instanceof Failed;
    }
}
