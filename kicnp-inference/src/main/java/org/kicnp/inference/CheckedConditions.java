package org.kicnp.inference;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.kicnp.core.Value;

/**
 * The condition part of an explanation: for each bound slot of a firing, its condition and the value it was tested
 * on (the candidate's value along the condition's left path, or the instance itself), taken when the frame fires so
 * that a later change does not rewrite history.
 */
final class CheckedConditions {
    private CheckedConditions() {
    }

    /**
     * The checked conditions of a firing of {@code r} with {@code binding} (slot → instance); {@code refs} are the
     * records of the facts bound to the required slots, in the rule's order, so their values are read without a
     * look-up by name.
     */
    static List<Derivation.CheckedCondition> of(Rule r, Map<String, String> binding, FactView.Fact[] refs,
            FactView facts, Conditions conditions) {
        List<Derivation.CheckedCondition> out = new ArrayList<>(r.patterns().size());
        List<SlotPattern> required = r.required();
        for (SlotPattern p : r.patterns()) {
            String fact = binding.get(p.slot());
            if (fact == null) {
                continue;
            }
            List<String> path = p.condition().testedPath().orElse(null);
            String value = fact;
            if (path != null) {
                int at = positionOf(required, p);
                Optional<Value> v = at >= 0 && at < refs.length && refs[at].name.equals(fact)
                        ? facts.follow(refs[at], path, conditions) : conditions.follow(Value.ref(fact), path);
                value = v.map(Value::text).orElse(fact);
            }
            out.add(new Derivation.CheckedCondition(p.slot(), p.conditionText(), value));
        }
        return out;
    }

    private static int positionOf(List<SlotPattern> required, SlotPattern p) {
        for (int i = 0; i < required.size(); i++) {
            if (required.get(i) == p) {
                return i;
            }
        }
        return -1;
    }
}
