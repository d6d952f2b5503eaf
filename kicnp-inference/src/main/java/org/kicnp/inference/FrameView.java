package org.kicnp.inference;

import java.util.AbstractMap;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.kicnp.core.EffectiveSlot;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.script.ScriptObject;

/**
 * A read-only view of an instance's effective slots for scripts: {@code s.mMouth}, {@code s.mUser.name}. Instance
 * references become nested views (a few levels deep), other values plain Java; {@code $name} and {@code $class}
 * give the frame's own name and class. A single slot is read when asked for ({@link #member}); all of them only when
 * the view is enumerated.
 */
final class FrameView extends AbstractMap<String, Object> implements ScriptObject {
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

    /** One slot, read when asked for: scripts read a few slots of a frame, not all of them. */
    @Override public Optional<Object> member(String key) {
        if (entries != null) {
            return Optional.ofNullable(entries.get(key));
        }
        if (NAME.equals(key)) {
            return Optional.of(frame);
        }
        if (!kb.contains(frame)) {
            return Optional.empty();
        }
        if ("$class".equals(key)) {
            return kb.frame(frame).flatMap(Frame::parent).map(p -> (Object) p);
        }
        return kb.value(frame, key).map(this::toJava);
    }

    @Override public Set<String> memberKeys() {
        return keySet();
    }

    @Override public Object get(Object key) {
        return key instanceof String k ? member(k).orElse(null) : null;
    }

    @Override public boolean containsKey(Object key) {
        return key instanceof String k && member(k).isPresent();
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
