package org.kicnp.inference;

import java.util.AbstractMap;
import java.util.AbstractSet;
import java.util.Iterator;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.Set;

/**
 * The binding being built while a new fact is joined: the fact at each required slot of the rule, by position
 * ({@code null} while unbound), read as a map slot → instance by the condition evaluator. A rule has a handful of
 * instance slots, so a linear search beats hashing, and a join allocates one small object instead of a hash table.
 * The map view is read-only; the matcher sets positions directly. Owned by the engine thread.
 */
final class JoinBinding extends AbstractMap<String, String> {
    private final String[] slots;
    /** The facts bound, by position; null where unbound. */
    final FactView.Fact[] refs;

    JoinBinding(String[] slots) {
        this.slots = slots;
        this.refs = new FactView.Fact[slots.length];
    }

    /** Whether the fact is bound at some position already (an instance fills one slot of a binding). */
    boolean holds(FactView.Fact fact) {
        for (FactView.Fact f : refs) {
            if (f == fact) {
                return true;
            }
        }
        return false;
    }

    @Override public String get(Object slot) {
        for (int i = 0; i < slots.length; i++) {
            if (slots[i] == slot || slots[i].equals(slot)) {
                return refs[i] == null ? null : refs[i].name;
            }
        }
        return null;
    }

    @Override public boolean containsKey(Object slot) {
        return get(slot) != null;
    }

    @Override public boolean containsValue(Object fact) {
        for (FactView.Fact f : refs) {
            if (f != null && f.name.equals(fact)) {
                return true;
            }
        }
        return false;
    }

    @Override public int size() {
        int n = 0;
        for (FactView.Fact f : refs) {
            if (f != null) {
                n++;
            }
        }
        return n;
    }

    @Override public Set<Map.Entry<String, String>> entrySet() {
        return new AbstractSet<>() {
            @Override public Iterator<Map.Entry<String, String>> iterator() {
                return new Iterator<>() {
                    private int next = skip(0);

                    private int skip(int i) {
                        while (i < refs.length && refs[i] == null) {
                            i++;
                        }
                        return i;
                    }

                    @Override public boolean hasNext() {
                        return next < refs.length;
                    }

                    @Override public Map.Entry<String, String> next() {
                        if (next >= refs.length) {
                            throw new NoSuchElementException();
                        }
                        int i = next;
                        next = skip(i + 1);
                        return new SimpleImmutableEntry<>(slots[i], refs[i].name);
                    }
                };
            }

            @Override public int size() {
                return JoinBinding.this.size();
            }
        };
    }
}
