package org.kicnp.inference;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import org.kicnp.core.Condition;
import org.kicnp.core.Operand;
import org.kicnp.core.Value;

/**
 * Evaluates declarative slot conditions. Slot values are read through a function (frame, slot) → value so that the
 * same code serves real instances and the hypothetical ones of backward chaining. Script conditions are not decided
 * here: the caller passes what they evaluate to.
 */
final class Conditions {
    /** The most steps of a path that are followed; the rest are not read. */
    static final int MAX_PATH = 32;

    /** Reads a slot of a frame: empty when the frame or the value is missing. */
    interface Reader {
        Optional<Value> value(String frame, String slot);
    }

    private final Reader reader;

    Conditions(Reader reader) {
        this.reader = reader;
    }

    /** Follows slot names from a value; each step needs a frame reference to continue. */
    Optional<Value> follow(Value start, List<String> path) {
        return follow(start, path, 0);
    }

    /** Follows {@code path} from its step {@code from} on, starting at {@code start}. */
    Optional<Value> follow(Value start, List<String> path, int from) {
        Value cur = start;
        for (int i = from; i < path.size() && i < MAX_PATH; i++) {
            if (!(cur instanceof Value.Ref r)) {
                return Optional.empty();
            }
            Optional<Value> next = reader.value(r.frame(), path.get(i));
            if (next.isEmpty()) {
                return Optional.empty();
            }
            cur = next.get();
        }
        return Optional.of(cur);
    }

    /**
     * Whether a declarative condition holds for the candidate {@code own} of a slot of {@code ruleFrame}, with
     * {@code binding} (slot → instance) giving the other slots. A path whose head is not bound is read from the
     * behavior frame itself. Script conditions count as holding here.
     */
    boolean holds(Condition c, Value own, String ruleFrame, Map<String, String> binding) {
        Function<Operand, Optional<Value>> rhs = o -> operand(o, ruleFrame, binding);
        return switch (c) {
            case Condition.Any a -> true;
            case Condition.Script s -> true;
            case Condition.Compare cmp -> {
                Optional<Value> l = follow(own, cmp.left());
                Optional<Value> r = rhs.apply(cmp.right());
                yield l.isPresent() && r.isPresent() && Values.test(l.get(), cmp.op(), r.get());
            }
            case Condition.Between b -> {
                Optional<Value> l = follow(own, b.left());
                Optional<Value> lo = rhs.apply(b.low());
                Optional<Value> hi = rhs.apply(b.high());
                yield l.isPresent() && lo.isPresent() && hi.isPresent()
                        && Values.test(l.get(), Condition.Op.GE, lo.get()) && Values.test(l.get(), Condition.Op.LE, hi.get());
            }
            case Condition.OneOf o -> {
                Optional<Value> l = follow(own, o.left());
                yield l.isPresent() && o.options().stream().map(rhs)
                        .anyMatch(v -> v.isPresent() && Values.test(l.get(), Condition.Op.EQ, v.get()));
            }
            case Condition.Matches m -> {
                Optional<Value> l = follow(own, m.left());
                yield l.isPresent() && !(l.get() instanceof Value.Lst) && l.get().text().matches(m.regex());
            }
        };
    }

    Optional<Value> operand(Operand o, String ruleFrame, Map<String, String> binding) {
        return switch (o) {
            case Operand.Constant c -> Optional.of(c.value());
            case Operand.Path p -> {
                String bound = binding.get(p.head());
                Optional<Value> start = bound != null ? Optional.of(Value.ref(bound)) : reader.value(ruleFrame, p.head());
                yield start.flatMap(v -> follow(v, p.steps().subList(1, p.steps().size())));
            }
        };
    }
}
