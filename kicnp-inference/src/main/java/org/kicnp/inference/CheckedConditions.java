package org.kicnp.inference;

import java.util.Arrays;
import java.util.List;
import java.util.Map;
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
        List<SlotPattern> patterns = r.patterns(); // the required slots in order, then the optional ones
        Derivation.CheckedCondition[] out = new Derivation.CheckedCondition[patterns.size()];
        int count = 0;
        for (int i = 0, n = patterns.size(); i < n; i++) {
            SlotPattern p = patterns.get(i);
            FactView.Fact record = i < refs.length ? refs[i] : null; // refs follow the required slots' order
            String fact = record != null ? record.name : binding.get(p.slot());
            if (fact == null) {
                continue;
            }
            List<String> path = p.condition().testedPath().orElse(null);
            String value = fact;
            if (path != null) {
                Value v = record != null ? facts.followOrNull(record, path, conditions)
                        : conditions.follow(Value.ref(fact), path).orElse(null);
                if (v != null) {
                    value = v.text();
                }
            }
            out[count++] = new Derivation.CheckedCondition(p.slot(), p.conditionText(), value);
        }
        return count == out.length ? List.of(out) : List.of(Arrays.copyOf(out, count));
    }

}
