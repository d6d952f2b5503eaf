package org.kicnp.inference;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.kicnp.core.Condition;
import org.kicnp.core.Value;

/**
 * The condition part of an explanation: for each bound slot of a firing, its condition and the value it was tested
 * on (the candidate's value along the condition's left path, or the instance itself), taken when the frame fires so
 * that a later change does not rewrite history.
 */
final class CheckedConditions {
    private CheckedConditions() {
    }

    static List<Derivation.CheckedCondition> of(Rule r, Map<String, String> binding, Conditions conditions) {
        List<Derivation.CheckedCondition> out = new ArrayList<>(r.patterns().size());
        for (SlotPattern p : r.patterns()) {
            String fact = binding.get(p.slot());
            if (fact == null) {
                continue;
            }
            String value = left(p.condition()).flatMap(path -> conditions.follow(Value.ref(fact), path))
                    .map(Value::text).orElse(fact);
            out.add(new Derivation.CheckedCondition(p.slot(), p.conditionText(), value));
        }
        return out;
    }

    /** The path a condition tests from the candidate, for the conditions that have one. */
    private static Optional<List<String>> left(Condition c) {
        return switch (c) {
            case Condition.Compare x -> Optional.of(x.left());
            case Condition.Between x -> Optional.of(x.left());
            case Condition.OneOf x -> Optional.of(x.left());
            case Condition.Matches x -> Optional.of(x.left());
            case Condition.Any x -> Optional.empty();
            case Condition.Script x -> Optional.empty();
        };
    }
}
