package org.kicnp.core;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The slot declarations a class inherits and makes: for each slot name, the nearest frame declaring it and the
 * nearest ARGUMENT given for it on the way up. Immutable; a class's set is its parent's plus its own slots, built
 * once per class ({@link ClassInfo}). A class sees a handful of slot names, so they are kept in an array searched
 * linearly, with a hash index only for large sets.
 */
final class Declarations {
    static final Declarations NONE = new Declarations(new Declaration[0]);
    private static final int LINEAR = 12;

    /** A slot as declared up the IS-A chain: the nearest declaration, and the nearest ARGUMENT at or above it. */
    record Declaration(String name, Slot slot, Frame declaredBy, String argument) {
    }

    private final Declaration[] items;
    private final Map<String, Integer> index;

    private Declarations(Declaration[] items) {
        this.items = items;
        if (items.length > LINEAR) {
            index = HashMap.newHashMap(items.length);
            for (int i = 0; i < items.length; i++) {
                index.put(items[i].name(), i);
            }
        } else {
            index = null;
        }
    }

    /** The declaration of that slot name, or null. */
    Declaration find(String name) {
        int at = indexOf(name);
        return at < 0 ? null : items[at];
    }

    /** These declarations overridden and extended by the slots of {@code frame}, a class directly below them. */
    Declarations plus(Frame frame) {
        List<Slot> own = frame.slots();
        if (own.isEmpty()) {
            return this;
        }
        Declaration[] out = Arrays.copyOf(items, items.length + own.size());
        int n = items.length;
        for (int i = 0, count = own.size(); i < count; i++) {
            Slot s = own.get(i);
            // Slot names are unique within a frame, so only the inherited entries can match.
            int at = indexOf(s.name());
            Declaration up = at < 0 ? null : items[at];
            String argument = s.argumentOrNull() != null ? s.argumentOrNull() : up == null ? null : up.argument();
            Declaration d = new Declaration(s.name(), s, frame, argument);
            if (at >= 0) {
                out[at] = d;
            } else {
                out[n++] = d;
            }
        }
        return new Declarations(n == out.length ? out : Arrays.copyOf(out, n));
    }

    private int indexOf(String name) {
        if (index != null) {
            Integer at = index.get(name);
            return at == null ? -1 : at;
        }
        for (int i = 0; i < items.length; i++) {
            String known = items[i].name();
            if (known == name || known.equals(name)) {
                return i;
            }
        }
        return -1;
    }
}
