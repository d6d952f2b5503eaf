package org.kicnp.editor;

import static java.util.Objects.requireNonNull;

import java.util.List;

/**
 * A robot tele-operation can command and the actions it offers, as the gateway's capabilities (or the simulator's
 * {@code hello}) describe them. The page builds its tele-operation form from this.
 *
 * @param kind what sort of robot it is ({@code humanoid}, {@code mobile}, {@code quadruped}); may be empty
 */
public record RobotCapabilities(String name, String kind, List<ActionSpec> actions) {
    public RobotCapabilities {
        requireNonNull(name, "name");
        requireNonNull(kind, "kind");
        actions = List.copyOf(actions);
    }

    /** One action: its name, a one-line description (may be empty) and its arguments. */
    public record ActionSpec(String name, String doc, List<ArgSpec> args) {
        public ActionSpec {
            requireNonNull(name, "name");
            requireNonNull(doc, "doc");
            args = List.copyOf(args);
        }
    }

    /** One argument: name, type as text ({@code number}, {@code string}, …) and whether it must be given. */
    public record ArgSpec(String name, String type, boolean required) {
        public ArgSpec {
            requireNonNull(name, "name");
            requireNonNull(type, "type");
        }
    }
}
