package org.kicnp.core;

import java.util.LinkedHashSet;
import java.util.Set;

/** The names of the frames a frame mentions, other than its parent: slot arguments and values, parts, links. */
final class References {
    private References() {
    }

    static Set<String> of(Frame f) {
        if (!mentionsAny(f)) {
            return Set.of();
        }
        Set<String> out = new LinkedHashSet<>();
        for (Slot s : f.slots()) {
            if (s.type() == DataType.INSTANCE || s.type() == DataType.FRAME
                    || s.type() == DataType.LIST && s.argument().filter(References::isClassArgument).isPresent()) {
                s.argument().ifPresent(out::add);
            }
            s.value().ifPresent(v -> addRefs(v, out));
            s.defaultValue().ifPresent(v -> addRefs(v, out));
            s.frameRelated().ifPresent(out::add);
            out.addAll(s.frameListRelated());
        }
        out.addAll(f.parts());
        f.linksTo().forEach(l -> out.add(l.frame()));
        f.linksFrom().forEach(l -> out.add(l.frame()));
        out.remove(f.name());
        return out;
    }

    /** Whether the frame may mention another frame at all; most frames of a large knowledge base do not. */
    private static boolean mentionsAny(Frame f) {
        if (!f.parts().isEmpty() || !f.linksTo().isEmpty() || !f.linksFrom().isEmpty()) {
            return true;
        }
        for (Slot s : f.slots()) {
            if (s.argument().isPresent() || s.frameRelated().isPresent() || !s.frameListRelated().isEmpty()
                    || s.value().filter(References::mayRefer).isPresent()
                    || s.defaultValue().filter(References::mayRefer).isPresent()) {
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

    private static void addRefs(Value v, Set<String> out) {
        switch (v) {
            case Value.Ref r -> out.add(r.frame());
            case Value.Lst l -> l.items().forEach(i -> addRefs(i, out));
            default -> { }
        }
    }
}
