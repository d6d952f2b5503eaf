package org.kicnp.inference;

import java.util.AbstractList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * A firing's binding, slot → instance, immutable and in the rule's slot order ({@link SlotBinding}: by position,
 * no hash table), every slot bound. The engine makes one per firing from the activation's arrays without copying
 * them (they are never changed once made) and hands the same object to the derivation, the checked conditions and
 * the trace, where a hash map was built and copied before.
 */
final class Binding extends SlotBinding {
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

    /** The slots, in order (immutable). */
    List<String> slotList() {
        return slots;
    }

    /** The bound instances by position; not to be changed. */
    String[] factArray() {
        return facts;
    }

    @Override int width() {
        return facts.length;
    }

    @Override String slotAt(int position) {
        return slots.get(position);
    }

    @Override String factAt(int position) {
        return facts[position];
    }

    /** Every position is bound. */
    @Override public int size() {
        return facts.length;
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
}
