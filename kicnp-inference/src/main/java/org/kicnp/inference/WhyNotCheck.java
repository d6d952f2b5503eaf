package org.kicnp.inference;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.BiFunction;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;

/**
 * Works out a {@link WhyNot}: the candidates of each required slot of a behavior frame, then every binding of them
 * with what forward chaining would make of it now, script conditions run as forward chaining runs them on matching
 * (given {@code s} only, they cannot change anything). Read-only; runs on the engine's thread, under its lock.
 */
final class WhyNotCheck {
    private final KnowledgeBase kb;
    private final Supports supports;
    private final Conditions conditions;
    /** Why a script condition of a binding is false or fails now, if one is ({@link ScriptCalls#conditionFailsNow}). */
    private final BiFunction<Rule, Map<String, String>, Optional<String>> scriptFails;
    private final int limit;

    WhyNotCheck(KnowledgeBase kb, Supports supports, BiFunction<Rule, Map<String, String>, Optional<String>> scriptFails,
                int limit) {
        this.kb = kb;
        this.supports = supports;
        this.conditions = new Conditions(kb::value);
        this.scriptFails = scriptFails;
        this.limit = limit;
    }

    /**
     * @param partial slot → instance: bindings are looked for with these slots held (each must be a required slot)
     * @param waiting the bindings on the agenda now
     */
    WhyNot check(Rule r, Map<String, String> partial, Set<BindingKey> waiting) {
        for (String slot : partial.keySet()) {
            if (r.pattern(slot).filter(SlotPattern::required).isEmpty()) {
                throw new IllegalArgumentException("Frame '" + r.frame() + "' has no required instance slot '" + slot
                        + "'; its required slots are " + r.requiredSlots() + ".");
            }
        }
        List<WhyNot.SlotCandidates> slots = new ArrayList<>();
        List<List<String>> pools = new ArrayList<>();
        for (SlotPattern p : r.required()) {
            List<String> candidates = new ArrayList<>();
            List<String> rejected = new ArrayList<>();
            int[] turnedAway = {0};
            String given = partial.get(p.slot());
            if (given != null) {
                Optional<Frame> f = kb.frame(given);
                if (f.isEmpty() || !f.get().isInstance() || !kb.isA(given, p.argument())) {
                    turnedAway[0]++;
                    rejected.add(given + ": " + (f.isEmpty() ? "there is no frame of that name"
                            : "not an instance of '" + p.argument() + "'"));
                } else {
                    sort(r, p, given, candidates, rejected, turnedAway);
                }
            } else {
                for (Frame f : kb.instancesOf(p.argument())) {
                    sort(r, p, f.name(), candidates, rejected, turnedAway);
                }
            }
            slots.add(new WhyNot.SlotCandidates(p.slot(), p.argument(), p.conditionText(),
                    candidates.subList(0, Math.min(limit, candidates.size())), rejected, candidates.size(),
                    turnedAway[0]));
            pools.add(candidates);
        }
        List<WhyNot.Verdict> verdicts = new ArrayList<>();
        boolean complete = pools.stream().noneMatch(List::isEmpty)
                && combine(r, pools, 0, new String[pools.size()], waiting, verdicts);
        return new WhyNot(r.frame(), slots, verdicts, !complete && pools.stream().noneMatch(List::isEmpty));
    }

    /**
     * A candidate goes to the slot's candidates, or is counted as turned away when its own condition is false for it
     * (and listed, with the value tested, while the list is under the limit).
     */
    private void sort(Rule r, SlotPattern p, String instance, List<String> candidates, List<String> rejected,
                      int[] turnedAway) {
        if (p.alpha() && !p.isScript() && !conditions.holds(p.condition(), Value.ref(instance), r.frame(), Map.of())) {
            turnedAway[0]++;
            if (rejected.size() < limit) {
                rejected.add(instance + ": " + falseFor(p, instance));
            }
        } else {
            candidates.add(instance);
        }
    }

    /** Every binding of distinct instances, in slot order; false when the limit cut it short. */
    private boolean combine(Rule r, List<List<String>> pools, int k, String[] chosen, Set<BindingKey> waiting,
                            List<WhyNot.Verdict> out) {
        if (k == pools.size()) {
            if (out.size() >= limit) {
                return false;
            }
            out.add(verdict(r, chosen.clone(), waiting));
            return true;
        }
        for (String c : pools.get(k)) {
            if (bound(chosen, k, c)) {
                continue; // forward chaining never binds one instance to two slots
            }
            chosen[k] = c;
            if (!combine(r, pools, k + 1, chosen, waiting, out)) {
                return false;
            }
        }
        chosen[k] = null;
        return true;
    }

    private static boolean bound(String[] chosen, int before, String c) {
        for (int i = 0; i < before; i++) {
            if (chosen[i].equals(c)) {
                return true;
            }
        }
        return false;
    }

    private WhyNot.Verdict verdict(Rule r, String[] facts, Set<BindingKey> waiting) {
        Map<String, String> binding = Activation.bindingOf(r, facts);
        for (SlotPattern p : r.required()) {
            String own = binding.get(p.slot());
            if (!p.isScript() && !conditions.holds(p.condition(), Value.ref(own), r.frame(), binding)) {
                return new WhyNot.Verdict(binding, WhyNot.Outcome.CONDITION_FALSE, "slot '" + p.slot() + "': "
                        + falseFor(p, own));
            }
        }
        BindingKey key = new BindingKey(r.frame(), facts);
        Optional<String> blocked = supports.blocked(r, facts, key);
        if (blocked.isPresent()) {
            return new WhyNot.Verdict(binding, WhyNot.Outcome.BLOCKED, blocked.get());
        }
        if (waiting.contains(key)) {
            return new WhyNot.Verdict(binding, WhyNot.Outcome.WAITING, "on the agenda: it fires when its turn comes");
        }
        if (r.scripted()) {
            Optional<String> fails = scriptFails.apply(r, binding);
            if (fails.isPresent()) {
                return new WhyNot.Verdict(binding, WhyNot.Outcome.SCRIPT_CONDITION, fails.get());
            }
            return new WhyNot.Verdict(binding, WhyNot.Outcome.WOULD_FIRE, "its script conditions hold now, but not "
                    + "when the engine matched the binding: a script runs when its binding is matched, and a binding is "
                    + "matched again when an instance it binds changes, not when something else the script reads does");
        }
        return new WhyNot.Verdict(binding, WhyNot.Outcome.WOULD_FIRE,
                "nothing that whyNot sees stops it, yet the engine has not matched it; run the engine");
    }

    /** "COND is false", with the value the condition tested when it tests a path of the candidate. */
    private String falseFor(SlotPattern p, String instance) {
        String tested = p.condition().testedPath()
                .map(path -> conditions.follow(Value.ref(instance), path)
                        .map(v -> " ('" + instance + "'." + String.join(".", path) + " is " + v.text() + ")")
                        .orElse(" ('" + instance + "' has no value at ." + String.join(".", path) + ")"))
                .orElse("");
        return p.conditionText() + " is false" + tested;
    }
}
