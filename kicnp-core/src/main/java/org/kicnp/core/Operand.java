package org.kicnp.core;

import static java.util.Objects.requireNonNull;

import java.util.List;

/** The right-hand side of a declarative condition: a constant, or a path through the binding ({@code mUser.name}). */
public sealed interface Operand permits Operand.Constant, Operand.Path {

    /** Canonical text, as the condition syntax writes it. */
    String text();

    /** A constant value. */
    record Constant(Value value) implements Operand {
        public Constant {
            requireNonNull(value, "value");
        }

        @Override public String text() {
            return switch (value) {
                case Value.Str s -> quote(s.value());
                case Value.Ref r -> "@" + r.frame();
                default -> value.text();
            };
        }

        private static String quote(String s) {
            return '"' + s.replace("\\", "\\\\").replace("\"", "\\\"") + '"';
        }
    }

    /**
     * A path: its first step names a slot of the frame being matched, each further step a slot of the instance the
     * previous step refers to. {@code mUser.name} is the name slot of the instance bound to {@code mUser}.
     */
    record Path(List<String> steps) implements Operand {
        public Path {
            steps = List.copyOf(steps);
            if (steps.isEmpty()) {
                throw new IllegalArgumentException("A slot path needs at least one slot name.");
            }
        }

        /** The slot of the matched frame that this path starts from. */
        public String head() {
            return steps.getFirst();
        }

        @Override public String text() {
            return String.join(".", steps);
        }
    }
}
