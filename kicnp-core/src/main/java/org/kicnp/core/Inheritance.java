package org.kicnp.core;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.Function;

/**
 * Slot look-up along the IS-A chain, in the manner of a lexical environment: the frame's own slot first, then its
 * parent's, and so on up to the root. The lowest declaration decides the type, flags and condition; facets it leaves
 * empty (argument, role, from, related frames, demons, a condition of ANY) are taken from the nearest ancestor that
 * gives them. The value is the nearest value or default found walking up: a lower frame's default therefore hides
 * an ancestor's value, and a default applies only where no value is given at that level or below.
 */
final class Inheritance {
    private static final int MAX_DEPTH = 100_000;

    private Inheritance() {
    }

    /** The frame and its ancestors, lowest first. {@code lookup} answers null for an unknown name. */
    static List<Frame> chain(Function<String, Frame> lookup, Frame frame) {
        List<Frame> chain = new ArrayList<>(8);
        Frame f = frame;
        while (f != null && chain.size() < MAX_DEPTH) {
            chain.add(f);
            f = parentOf(lookup, f);
        }
        return chain;
    }

    static Optional<EffectiveSlot> slot(Function<String, Frame> lookup, Frame frame, String slotName) {
        return merge(chain(lookup, frame), slotName);
    }

    /**
     * The slot's effective value, as {@code slot(...).effectiveValue()} gives it, without merging facets when the
     * lowest declaration holds a value or default itself (the common case: an instance's own slot value, a behavior
     * frame's script): walking up stops there. Otherwise the full merge decides, since an ancestor's value may not
     * fit the lower declaration.
     */
    static Optional<Value> value(Function<String, Frame> lookup, Frame frame, String slotName) {
        Frame f = frame;
        for (int depth = 0; f != null && depth < MAX_DEPTH; depth++) {
            Slot own = f.ownSlotOrNull(slotName);
            if (own != null) {
                Value v = own.valueOrNull() != null ? own.valueOrNull() : own.defaultOrNull();
                return v != null ? Optional.of(v) : slot(lookup, frame, slotName).flatMap(e -> e.slot().effectiveValue());
            }
            f = parentOf(lookup, f);
        }
        return Optional.empty();
    }

    private static Frame parentOf(Function<String, Frame> lookup, Frame f) {
        String p = f.parentOrNull();
        return p == null ? null : lookup.apply(p);
    }

    static List<EffectiveSlot> slots(Function<String, Frame> lookup, Frame frame) {
        List<Frame> chain = chain(lookup, frame);
        Set<String> names = new LinkedHashSet<>();
        for (int i = chain.size() - 1; i >= 0; i--) {
            chain.get(i).slots().forEach(s -> names.add(s.name()));
        }
        List<EffectiveSlot> out = new ArrayList<>(names.size());
        for (String n : names) {
            merge(chain, n).ifPresent(out::add);
        }
        return out;
    }

    private static Optional<EffectiveSlot> merge(List<Frame> chain, String slotName) {
        Slot lowest = null;
        String declaredBy = null;
        Slot.Builder merged = null;
        String valueFrom = null;
        boolean needArgument = true, needRole = true, needFrom = true, needRelated = true, needList = true;
        boolean needCondition = true, needValue = true, needNeeded = true, needAdded = true, needRemoved = true;
        for (Frame f : chain) {
            Slot s = f.ownSlotOrNull(slotName);
            if (s == null) {
                continue;
            }
            if (lowest == null) {
                lowest = s;
                declaredBy = f.name();
                merged = s.toBuilder().clearValue().clearDefault();
            }
            if (needArgument && s.argument().isPresent()) {
                merged.argument(s.argument().get());
                needArgument = false;
            }
            if (needRole && s.role().isPresent()) {
                merged.role(s.role().get());
                needRole = false;
            }
            if (needFrom && s.from().isPresent()) {
                merged.from(s.from().get());
                needFrom = false;
            }
            if (needRelated && s.frameRelated().isPresent()) {
                merged.frameRelated(s.frameRelated().get());
                needRelated = false;
            }
            if (needList && !s.frameListRelated().isEmpty()) {
                merged.frameListRelated(s.frameListRelated());
                needList = false;
            }
            if (needCondition && !(s.condition() instanceof Condition.Any)) {
                merged.condition(s.condition());
                needCondition = false;
            }
            if (needNeeded && s.onNeeded().isPresent()) {
                merged.onNeeded(s.onNeeded().get());
                needNeeded = false;
            }
            if (needAdded && s.onAdded().isPresent()) {
                merged.onAdded(s.onAdded().get());
                needAdded = false;
            }
            if (needRemoved && s.onRemoved().isPresent()) {
                merged.onRemoved(s.onRemoved().get());
                needRemoved = false;
            }
            if (needValue && (s.value().isPresent() || s.defaultValue().isPresent())) {
                if (s.value().isPresent()) {
                    merged.value(s.value().get());
                } else {
                    merged.defaultValue(s.defaultValue().get());
                }
                valueFrom = f.name();
                needValue = false;
            }
        }
        if (lowest == null) {
            return Optional.empty();
        }
        Slot result;
        try {
            result = merged.build();
        } catch (InvalidFrameException e) {
            // An ancestor's value does not fit the type the lower frame declares: report the lower declaration as is.
            result = lowest;
            valueFrom = declaredBy;
        }
        return Optional.of(new EffectiveSlot(result, declaredBy, valueFrom == null ? declaredBy : valueFrom));
    }
}
