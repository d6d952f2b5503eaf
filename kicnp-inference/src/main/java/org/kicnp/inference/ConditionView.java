package org.kicnp.inference;

import java.util.AbstractMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.script.ScriptObject;

/**
 * The {@code s} of a script condition: each bound slot's instance as a read-only view ({@link FrameView}), read when
 * the script asks for it, noting whether the script asked for anything but the condition's own slot. A run that read
 * only its own slot (and what it reaches through it) gave an outcome that rests on that slot's instance alone: the
 * engine may keep it for every binding with that instance there ({@link ScriptCalls#conditionFails}), as a Rete alpha
 * node tests a one-fact constraint once per fact rather than once per join.
 *
 * <p>A map too, for script hosts that read {@code s} as one: {@link #get} notes the key as a script's read does, and
 * anything that lists the entries counts as reading them all.
 */
final class ConditionView extends AbstractMap<String, Object> implements ScriptObject {
    private final KnowledgeBase kb;
    private final Map<String, String> binding;
    private final String own;
    private boolean readOther;

    ConditionView(KnowledgeBase kb, Map<String, String> binding, String own) {
        this.kb = kb;
        this.binding = binding;
        this.own = own;
    }

    /**
     * Whether the script asked for a member other than its own slot: another slot (bound or not — an optional slot
     * left empty reads as nothing here and as an instance in another binding), or the list of members.
     */
    boolean readOther() {
        return readOther;
    }

    @Override public Optional<Object> member(String key) {
        if (!own.equals(key)) {
            readOther = true;
        }
        String fact = binding.get(key);
        return fact == null ? Optional.empty() : Optional.of(new FrameView(kb, fact, 0));
    }

    @Override public Set<String> memberKeys() {
        readOther = true;
        return binding.keySet();
    }

    @Override public Object get(Object key) {
        return key instanceof String k ? member(k).orElse(null) : null;
    }

    @Override public boolean containsKey(Object key) {
        return key instanceof String k && member(k).isPresent();
    }

    @Override public Set<Entry<String, Object>> entrySet() {
        readOther = true;
        Map<String, Object> all = new LinkedHashMap<>();
        binding.forEach((slot, fact) -> all.put(slot, new FrameView(kb, fact, 0)));
        return all.entrySet();
    }

    @Override public String toString() {
        return "binding" + binding.keySet();
    }
}
