package org.kicnp.core;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Optional;
import java.util.regex.PatternSyntaxException;

/**
 * The condition facet of a slot. Declarative conditions compare the slot's value (or a slot of the instance it
 * holds, reached by {@code left}) with a constant or with another slot of the binding, so that the inference engine
 * can index them; {@link Script} holds JavaScript for what cannot be said declaratively.
 * The text syntax is documented in {@code docs/knowledge-model.md} and parsed by {@link ConditionParser}.
 */
public sealed interface Condition
        permits Condition.Any, Condition.Compare, Condition.Between, Condition.OneOf, Condition.Matches,
                Condition.Script {

    /** The condition that every value satisfies ({@code COND_ANY}). */
    Any ANY = new Any();

    /** Canonical text of the condition; {@code ConditionParser.parse(c.text())} gives {@code c} back. */
    String text();

    /** What the tested value is compared with: the constants and paths (none for COND_ANY, matches and scripts). */
    default List<Operand> operands() {
        return switch (this) {
            case Compare c -> List.of(c.right());
            case Between b -> List.of(b.low(), b.high());
            case OneOf o -> o.options();
            case Any a -> List.of();
            case Matches m -> List.of();
            case Script s -> List.of();
        };
    }

    /**
     * The path the condition tests from the slot's value ({@code .status == "ended"}: [status]; an empty list: the
     * value itself), or empty for COND_ANY and scripts, which test no path.
     */
    default Optional<List<String>> testedPath() {
        return switch (this) {
            case Compare c -> Optional.of(c.left());
            case Between b -> Optional.of(b.left());
            case OneOf o -> Optional.of(o.left());
            case Matches m -> Optional.of(m.left());
            case Any a -> Optional.empty();
            case Script s -> Optional.empty();
        };
    }

    /** Comparison operators. */
    enum Op {
        EQ("=="), NE("!="), LT("<"), LE("<="), GT(">"), GE(">=");

        private final String symbol;

        Op(String symbol) {
            this.symbol = symbol;
        }

        public String symbol() {
            return symbol;
        }
    }

    /** Always true. */
    record Any() implements Condition {
        @Override public String text() {
            return "COND_ANY";
        }
    }

    /** {@code [.left] OP operand}: the slot's value, or the slot reached by {@code left} from it, compared. */
    record Compare(List<String> left, Op op, Operand right) implements Condition {
        public Compare {
            left = List.copyOf(left);
            requireNonNull(op, "op");
            requireNonNull(right, "right");
        }

        @Override public String text() {
            return leftText(left) + op.symbol() + " " + right.text();
        }
    }

    /** {@code [.left] between low and high}, both ends included. */
    record Between(List<String> left, Operand low, Operand high) implements Condition {
        public Between {
            left = List.copyOf(left);
            requireNonNull(low, "low");
            requireNonNull(high, "high");
        }

        @Override public String text() {
            return leftText(left) + "between " + low.text() + " and " + high.text();
        }
    }

    /** {@code [.left] in (a, b, c)}: membership in a set of operands. */
    record OneOf(List<String> left, List<Operand> options) implements Condition {
        public OneOf {
            left = List.copyOf(left);
            options = List.copyOf(options);
            if (options.isEmpty()) {
                throw new IllegalArgumentException("A membership condition needs at least one option.");
            }
        }

        @Override public String text() {
            StringBuilder sb = new StringBuilder(leftText(left)).append("in (");
            for (int i = 0; i < options.size(); i++) {
                sb.append(i == 0 ? "" : ", ").append(options.get(i).text());
            }
            return sb.append(')').toString();
        }
    }

    /** {@code [.left] matches "regex"}: the value's text matches a Java regular expression (whole match). */
    record Matches(List<String> left, String regex) implements Condition {
        public Matches {
            left = List.copyOf(left);
            requireNonNull(regex, "regex");
            try {
                java.util.regex.Pattern.compile(regex);
            } catch (PatternSyntaxException e) {
                throw new IllegalArgumentException("'" + regex + "' is not a valid pattern: " + e.getDescription() + ".");
            }
        }

        @Override public String text() {
            return leftText(left) + "matches " + new Operand.Constant(Value.of(regex)).text();
        }
    }

    /** A JavaScript expression evaluated by the inference engine with the binding as {@code s}. */
    record Script(String source) implements Condition {
        public Script {
            requireNonNull(source, "source");
            if (source.isBlank()) {
                throw new IllegalArgumentException("A script condition needs a script.");
            }
        }

        @Override public String text() {
            return "js: " + source;
        }
    }

    private static String leftText(List<String> left) {
        return left.isEmpty() ? "" : "." + String.join(".", left) + " ";
    }
}
