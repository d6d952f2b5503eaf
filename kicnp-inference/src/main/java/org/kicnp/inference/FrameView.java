package org.kicnp.inference;

import java.util.AbstractMap;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.kicnp.core.EffectiveSlot;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;

/**
 * A read-only view of an instance's effective slots for scripts: {@code s.mMouth}, {@code s.mUser.name}. Instance
 * references become nested views (a few levels deep), other values plain Java; {@code $name} and {@code $class}
 * give the frame's own name and class. Built lazily, on first read.
 */
final class FrameView extends AbstractMap<String, Object> {
    static final String NAME = "$name";
    private static final int MAX_DEPTH = 4;
    private final KnowledgeBase kb;
    private final String frame;
    private final int depth;
    private Map<String, Object> entries;

    FrameView(KnowledgeBase kb, String frame, int depth) {
        this.kb = kb;
        this.frame = frame;
        this.depth = depth;
    }

    /** The frame name behind a script value: a view, a map with {@code $name}, or a plain string. */
    static String nameOf(Object o) {
        if (o instanceof FrameView v) {
            return v.frame;
        }
        if (o instanceof Map<?, ?> m && m.get(NAME) instanceof String s) {
            return s;
        }
        if (o == null) {
            throw new InferenceException("A frame was expected but the script passed nothing.");
        }
        return o.toString();
    }

    @Override public Set<Entry<String, Object>> entrySet() {
        if (entries == null) {
            entries = new LinkedHashMap<>();
            entries.put(NAME, frame);
            kb.frame(frame).ifPresent(f -> {
                f.parent().ifPresent(p -> entries.put("$class", p));
                for (EffectiveSlot e : kb.slots(frame)) {
                    e.slot().effectiveValue().ifPresent(v -> entries.put(e.slot().name(), toJava(v)));
                }
            });
            entries = Collections.unmodifiableMap(entries);
        }
        return entries.entrySet();
    }

    private Object toJava(Value v) {
        return switch (v) {
            case Value.Str s -> s.value();
            case Value.Int i -> i.value();
            case Value.Real r -> r.value();
            case Value.Bool b -> b.value();
            case Value.Ref r -> depth < MAX_DEPTH && kb.contains(r.frame()) ? new FrameView(kb, r.frame(), depth + 1)
                    : r.frame();
            case Value.Lst l -> {
                List<Object> out = new ArrayList<>();
                l.items().forEach(x -> out.add(toJava(x)));
                yield List.copyOf(out);
            }
        };
    }
}
