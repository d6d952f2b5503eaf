package org.kicnp.inference;

import java.util.AbstractList;
import java.util.AbstractMap;
import java.util.AbstractSet;
import java.util.Collection;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.Objects;
import java.util.Set;
import java.util.function.BiConsumer;

/**
 * A firing's binding, slot → instance, immutable and in the rule's slot order: two arrays instead of a hash table.
 * A rule has a handful of instance slots, so {@link #get} searches linearly. The engine makes one per firing from
 * the activation's arrays without copying them (they are never changed once made) and hands the same object to
 * the derivation, the checked conditions and the trace, where a hash map was built and copied before.
 */
final class Binding extends AbstractMap<String, String> {
    private static final Binding EMPTY = new Binding(List.of(), new String[0]);

    private final List<String> slots;
    private final String[] facts;

    private Binding(List<String> slots, String[] facts) {
        this.slots = slots;
        this.facts = facts;
    }

    /**
     * The binding of {@code slots.get(i)} to {@code facts[i]}; the array is not copied, so the caller must never
     * change it afterwards. {@code slots} is an immutable list of distinct names; no entry is null.
     */
    static Binding wrap(List<String> slots, String[] facts) {
        if (slots.size() != facts.length) {
            throw new IllegalArgumentException("A binding needs one instance per slot: " + slots.size()
                    + " slots, " + facts.length + " instances.");
        }
        return new Binding(slots, facts);
    }

    /** The binding as an immutable {@code Binding} in the map's iteration order; the map itself if it is one. */
    static Binding copyOf(Map<String, String> binding) {
        if (binding instanceof Binding b) {
            return b;
        }
        if (binding.isEmpty()) {
            return EMPTY;
        }
        String[] s = new String[binding.size()];
        String[] f = new String[s.length];
        int i = 0;
        for (Map.Entry<String, String> e : binding.entrySet()) {
            s[i] = Objects.requireNonNull(e.getKey(), "slot");
            f[i++] = Objects.requireNonNull(e.getValue(), () -> "the instance bound to " + e.getKey());
        }
        return new Binding(List.of(s), f);
    }

    @Override public String get(Object slot) {
        for (int i = 0; i < facts.length; i++) {
            String s = slots.get(i);
            if (s == slot || s.equals(slot)) {
                return facts[i];
            }
        }
        return null;
    }

    @Override public boolean containsKey(Object slot) {
        return get(slot) != null;
    }

    @Override public boolean containsValue(Object fact) {
        for (String f : facts) {
            if (f.equals(fact)) {
                return true;
            }
        }
        return false;
    }

    @Override public int size() {
        return facts.length;
    }

    @Override public void forEach(BiConsumer<? super String, ? super String> action) {
        for (int i = 0; i < facts.length; i++) {
            action.accept(slots.get(i), facts[i]);
        }
    }

    /** The bound instances in slot order (a read-only view). */
    @Override public Collection<String> values() {
        return new AbstractList<>() {
            @Override public String get(int index) {
                return facts[index];
            }

            @Override public int size() {
                return facts.length;
            }
        };
    }

    @Override public Set<Map.Entry<String, String>> entrySet() {
        return new AbstractSet<>() {
            @Override public Iterator<Map.Entry<String, String>> iterator() {
                return new Iterator<>() {
                    private int next;

                    @Override public boolean hasNext() {
                        return next < facts.length;
                    }

                    @Override public Map.Entry<String, String> next() {
                        if (next >= facts.length) {
                            throw new NoSuchElementException();
                        }
                        int i = next++;
                        return new SimpleImmutableEntry<>(slots.get(i), facts[i]);
                    }
                };
            }

            @Override public int size() {
                return facts.length;
            }
        };
    }
}
