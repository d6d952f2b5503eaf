package org.kicnp.core;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/** The names of the frames a frame mentions, other than its parent: slot arguments and values, parts, links. */
final class References {
    private References() {
    }

    /** Each name the frame mentions once, in order, its own name left out. */
    static Set<String> of(Frame f) {
        if (!mentionsAny(f)) {
            return Set.of();
        }
        List<String> all = new ArrayList<>();
        collect(f, all);
        Set<String> out = new LinkedHashSet<>(all);
        out.remove(f.name());
        return out;
    }

    /**
     * Adds the names the frame mentions to {@code out}, in order, possibly more than once and possibly its own name:
     * the allocation-free form for callers that keep sets anyway (the indexes) or check each name (validation).
     */
    static void collect(Frame f, List<String> out) {
        if (!mentionsAny(f)) {
            return;
        }
        List<Slot> slots = f.slots();
        for (int i = 0, n = slots.size(); i < n; i++) {
            Slot s = slots.get(i);
            String argument = s.argumentOrNull();
            if (argument != null && (s.type() == DataType.INSTANCE || s.type() == DataType.FRAME
                    || s.type() == DataType.LIST && isClassArgument(argument))) {
                out.add(argument);
            }
            addRefs(s.valueOrNull(), out);
            addRefs(s.defaultOrNull(), out);
            if (s.frameRelatedOrNull() != null) {
                out.add(s.frameRelatedOrNull());
            }
            if (!s.frameListRelated().isEmpty()) { // addAll of an empty list still copies it to an array
                out.addAll(s.frameListRelated());
            }
        }
        if (!f.parts().isEmpty()) {
            out.addAll(f.parts());
        }
        for (SemanticLink l : f.linksTo()) {
            out.add(l.frame());
        }
        for (SemanticLink l : f.linksFrom()) {
            out.add(l.frame());
        }
    }

    /** Whether the frame may mention another frame at all; most frames of a large knowledge base do not. */
    private static boolean mentionsAny(Frame f) {
        if (!f.parts().isEmpty() || !f.linksTo().isEmpty() || !f.linksFrom().isEmpty()) {
            return true;
        }
        List<Slot> slots = f.slots();
        for (int i = 0, n = slots.size(); i < n; i++) {
            Slot s = slots.get(i);
            if (s.argumentOrNull() != null || s.frameRelatedOrNull() != null || !s.frameListRelated().isEmpty()
                    || mayRefer(s.valueOrNull()) || mayRefer(s.defaultOrNull())) {
                return true;
            }
        }
        return false;
    }

    private static boolean mayRefer(Value v) {
        return v instanceof Value.Ref || v instanceof Value.Lst;
    }

    /** A list's argument names a class unless it names a scalar data type. */
    static boolean isClassArgument(String argument) {
        return DataType.parse(argument).isEmpty();
    }

    private static void addRefs(Value v, List<String> out) {
        switch (v) {
            case Value.Ref r -> out.add(r.frame());
            case Value.Lst l -> {
                for (Value i : l.items()) {
                    addRefs(i, out);
                }
            }
            case null, default -> { }
        }
    }
}
