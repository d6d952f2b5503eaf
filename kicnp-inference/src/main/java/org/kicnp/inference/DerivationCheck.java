package org.kicnp.inference;

import java.util.Map;
import java.util.Optional;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;

/**
 * Whether a derived instance's derivation still holds after what it rests on, or its behavior frame, changed: each
 * bound instance still there and of its slot's class, each slot condition and script condition still true under the
 * rules as they are now. Asked by the forward chainer before it retracts; owned by the engine thread.
 */
final class DerivationCheck {
    private final KnowledgeBase kb;
    private final Conditions conditions;
    private final ScriptCalls scripts;
    private final Supports supports;
    /** The forward chainer's installed rules by frame (read, never changed here). */
    private final Map<String, Rule> rules;

    DerivationCheck(KnowledgeBase kb, Conditions conditions, ScriptCalls scripts, Supports supports,
                    Map<String, Rule> rules) {
        this.kb = kb;
        this.conditions = conditions;
        this.scripts = scripts;
        this.supports = supports;
        this.rules = rules;
    }

    /**
     * The first slot of a derived instance whose class or condition no longer holds ({@code "script"} for a script
     * condition), if any. An instance a script created, or one whose frame is no longer a behavior frame, holds.
     */
    Optional<String> failingSlot(Derivation d) {
        Rule r = rules.get(d.frame());
        if (r == null || d.createdBy().isPresent()) {
            return Optional.empty();
        }
        for (SlotPattern p : r.patterns()) {
            String fact = d.binding().get(p.slot());
            if (fact == null) {
                if (p.required()) {
                    return Optional.of(p.slot());
                }
                continue;
            }
            if (!kb.contains(fact) || !kb.isA(fact, p.argument())
                    || !conditions.holds(p.condition(), Value.ref(fact), r.frame(), d.binding())) {
                return Optional.of(p.slot());
            }
        }
        return scripts.conditionFails(r, Activation.bindingOf(r, Activation.factsOf(r, d.binding())))
                .map(x -> "script");
    }

    /**
     * Why a waiting binding of a rule's required slots no longer holds, if it does not: the first slot whose condition
     * is false now, or a false (or failing) script condition.
     */
    Optional<String> failing(Rule r, Binding binding) {
        for (SlotPattern p : r.required()) {
            if (!conditions.holds(p.condition(), Value.ref(binding.get(p.slot())), r.frame(), binding)) {
                return Optional.of("the condition of slot '" + p.slot() + "' no longer holds");
            }
        }
        return r.scripted() ? scripts.conditionFails(r, binding) : Optional.empty();
    }

    /** Lets the derivation's binding fire again once its instance is retracted (refraction no longer applies). */
    void unmarkFired(Derivation d) {
        Rule r = rules.get(d.frame());
        if (r != null) {
            supports.unmarkFired(new BindingKey(r.frame(), Activation.factsOf(r, d.binding())));
        }
    }
}
