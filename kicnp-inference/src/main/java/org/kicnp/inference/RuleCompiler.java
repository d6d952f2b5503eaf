package org.kicnp.inference;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.kicnp.core.Condition;
import org.kicnp.core.DataType;
import org.kicnp.core.EffectiveSlot;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Operand;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * Turns a class frame into a {@link Rule} when it is a behavior frame: a class whose effective slots (inherited ones
 * included) contain at least one required instance slot. Conditions are sorted into alpha tests (constants only),
 * joins (paths through other instance slots) and script conditions.
 */
final class RuleCompiler {
    private final KnowledgeBase kb;

    RuleCompiler(KnowledgeBase kb) {
        this.kb = kb;
    }

    Optional<Rule> compile(String frameName) {
        Optional<Frame> frame = kb.frame(frameName);
        if (frame.isEmpty() || !frame.get().isClass()) {
            return Optional.empty();
        }
        List<EffectiveSlot> slots = kb.slots(frameName);
        Set<String> instanceSlots = new HashSet<>();
        for (EffectiveSlot e : slots) {
            if (e.slot().type() == DataType.INSTANCE && e.slot().argument().isPresent()) {
                instanceSlots.add(e.slot().name());
            }
        }
        List<SlotPattern> required = new ArrayList<>();
        List<SlotPattern> optional = new ArrayList<>();
        int conditions = 0;
        int index = 0;
        for (EffectiveSlot e : slots) {
            Slot s = e.slot();
            if (!instanceSlots.contains(s.name())) {
                continue;
            }
            SlotPattern p = pattern(index++, s, instanceSlots);
            if (!(s.condition() instanceof Condition.Any)) {
                conditions++;
            }
            (s.required() ? required : optional).add(p);
        }
        if (required.isEmpty()) {
            return Optional.empty();
        }
        Optional<String> script = kb.value(frameName, "onInstantiate").map(Value::text).filter(t -> !t.isBlank());
        Optional<String> onDestroy = kb.value(frameName, "onDestroy").map(Value::text).filter(t -> !t.isBlank());
        return Optional.of(Rule.of(frameName, frame.get().priority(), kb.ancestors(frameName).size(), conditions,
                required, optional, script, onDestroy));
    }

    private static SlotPattern pattern(int index, Slot s, Set<String> instanceSlots) {
        Condition c = s.condition();
        Set<String> joins = new HashSet<>();
        for (Operand o : c.operands()) {
            if (o instanceof Operand.Path p && instanceSlots.contains(p.head()) && !p.head().equals(s.name())) {
                joins.add(p.head());
            }
        }
        Optional<SlotPattern.EqualityJoin> eq = Optional.empty();
        if (c instanceof Condition.Compare cmp && cmp.op() == Condition.Op.EQ && cmp.right() instanceof Operand.Path p
                && joins.contains(p.head())) {
            eq = Optional.of(new SlotPattern.EqualityJoin(cmp.left(), p.head(), p.steps().subList(1, p.steps().size())));
        }
        boolean alpha = joins.isEmpty() && !(c instanceof Condition.Script);
        return new SlotPattern(index, s.name(), s.argument().orElseThrow(), c, c.text(), s.required(), s.shared(),
                s.unique(), alpha, joins, eq);
    }
}
