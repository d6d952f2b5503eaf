package org.kicnp.inference;

import java.util.AbstractMap;
import java.util.AbstractSet;
import java.util.Iterator;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.Set;

/**
 * The binding being built while a new fact is joined (slot → instance), kept in two small arrays: a rule has a
 * handful of instance slots, so a linear search beats hashing, and the join allocates one small object instead of a
 * hash table per attempt. Only what the matcher uses is supported: get, put, remove, containsKey, containsValue and
 * iteration. Owned by the engine thread.
 */
final class SlotBinding extends AbstractMap<String, String> {
    private final String[] slots;
    private final String[] facts;
    private int size;

    SlotBinding(int capacity) {
        slots = new String[capacity];
        facts = new String[capacity];
    }

    private int indexOf(Object slot) {
        for (int i = 0; i < size; i++) {
            if (slots[i] == slot || slots[i].equals(slot)) {
                return i;
            }
        }
        return -1;
    }

    @Override public String get(Object slot) {
        int i = indexOf(slot);
        return i < 0 ? null : facts[i];
    }

    @Override public boolean containsKey(Object slot) {
        return indexOf(slot) >= 0;
    }

    @Override public boolean containsValue(Object fact) {
        for (int i = 0; i < size; i++) {
            if (facts[i].equals(fact)) {
                return true;
            }
        }
        return false;
    }

    @Override public String put(String slot, String fact) {
        int i = indexOf(slot);
        if (i >= 0) {
            String old = facts[i];
            facts[i] = fact;
            return old;
        }
        if (size == slots.length) {
            throw new IllegalStateException("A binding of " + slots.length + " slots cannot take slot '" + slot + "'.");
        }
        slots[size] = slot;
        facts[size++] = fact;
        return null;
    }

    @Override public String remove(Object slot) {
        int i = indexOf(slot);
        if (i < 0) {
            return null;
        }
        String old = facts[i];
        size--;
        slots[i] = slots[size];
        facts[i] = facts[size];
        slots[size] = null;
        facts[size] = null;
        return old;
    }

    @Override public int size() {
        return size;
    }

    @Override public Set<Map.Entry<String, String>> entrySet() {
        return new AbstractSet<>() {
            @Override public Iterator<Map.Entry<String, String>> iterator() {
                return new Iterator<>() {
                    private int next;

                    @Override public boolean hasNext() {
                        return next < size;
                    }

                    @Override public Map.Entry<String, String> next() {
                        if (next >= size) {
                            throw new NoSuchElementException();
                        }
                        int i = next++;
                        return new SimpleImmutableEntry<>(slots[i], facts[i]);
                    }
                };
            }

            @Override public int size() {
                return size;
            }
        };
    }
}
