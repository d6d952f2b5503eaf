package org.kicnp.core;

import static java.util.Objects.requireNonNull;

import java.util.Locale;

/**
 * The relation carried by a semantic link. The paper's three coordination relations are built in and given
 * meaning by the inference engine; users may add relations of their own by name.
 */
public sealed interface Relation permits Relation.Coordination, Relation.Named {

    /** The name as the XML format writes it. */
    String name();

    /** The paper's coordination relations (section 3.3). */
    enum Coordination implements Relation {
        /** Several robots act at once, their commands on one time coordinate. */
        SYNCHRONIZATION,
        /** An action starts only after another action has ended. */
        SUCCESSION,
        /** While this action runs, other robots perform no action. */
        RESTRICTION
    }

    /** A relation of the user's own, with no built-in meaning. */
    record Named(String name) implements Relation {
        public Named {
            requireNonNull(name, "name");
            if (name.isBlank()) {
                throw new IllegalArgumentException("A relation needs a name.");
            }
        }
    }

    /** Reads a relation name; the three built-in names are matched case-insensitively. */
    static Relation parse(String text) {
        String t = text.strip();
        try {
            return Coordination.valueOf(t.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            return new Named(t);
        }
    }
}
