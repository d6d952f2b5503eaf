package org.kicnp.inference;

import java.util.Arrays;
import java.util.Iterator;
import java.util.NoSuchElementException;
import java.util.function.Function;

/**
 * A map from instance names to the engine's records, in flat arrays: open addressing with linear probing, each slot's
 * hash kept beside its key. The engine looks a name up for every knowledge-base event and grows the table by the
 * hundred thousand within one run; a {@link java.util.HashMap} there chases one entry object per name on every probe
 * and every resize, this table reads arrays (a miss stops at an empty slot of the hash array, a resize walks the
 * arrays in order). Removal shifts the following entries back, so there are no tombstones. Null keys and values are
 * not allowed. Not thread-safe: owned by the engine thread.
 *
 * @param <V> the record type
 */
final class NameTable<V> implements Iterable<V> {
    private static final int MIN_CAPACITY = 16;
    private String[] keys;
    private Object[] values;
    private int[] hashes;
    private int size;
    private int shift;

    NameTable() {
        allocate(MIN_CAPACITY);
    }

    int size() {
        return size;
    }

    @SuppressWarnings("unchecked")
    V get(String key) {
        return (V) values[slotOf(key, key.hashCode())];
    }

    /** The value of {@code key}, made by {@code make} and stored when there is none (one probe sequence either way). */
    @SuppressWarnings("unchecked")
    V computeIfAbsent(String key, Function<String, V> make) {
        int h = key.hashCode();
        int i = slotOf(key, h);
        if (keys[i] != null) {
            return (V) values[i];
        }
        V v = make.apply(key);
        keys[i] = key;
        values[i] = v;
        hashes[i] = h;
        if (++size * 2 > keys.length) {
            allocate(keys.length * 2);
        }
        return v;
    }

    /** Removes the entry of {@code key}; returns its value, or null when there was none. */
    @SuppressWarnings("unchecked")
    V remove(String key) {
        int i = slotOf(key, key.hashCode());
        if (keys[i] == null) {
            return null;
        }
        V old = (V) values[i];
        size--;
        closeGap(i);
        return old;
    }

    /** The slot holding {@code key} (of hash {@code h}), or the empty slot that ends its probe run. */
    private int slotOf(String key, int h) {
        int mask = keys.length - 1;
        for (int i = slot(h); ; i = i + 1 & mask) {
            String k = keys[i];
            if (k == null || hashes[i] == h && (k == key || k.equals(key))) {
                return i;
            }
        }
    }

    /** Backward-shift deletion: moves later entries of the probe run into the gap at {@code gap}. */
    private void closeGap(int gap) {
        int mask = keys.length - 1;
        int i = gap;
        while (true) {
            i = i + 1 & mask;
            if (keys[i] == null) {
                break;
            }
            int home = slot(hashes[i]);
            // The entry at i may move to the gap when its home is not in the cyclic range (gap, i].
            boolean movable = gap <= i ? home <= gap || home > i : home <= gap && home > i;
            if (movable) {
                keys[gap] = keys[i];
                values[gap] = values[i];
                hashes[gap] = hashes[i];
                gap = i;
            }
        }
        keys[gap] = null;
        values[gap] = null;
        hashes[gap] = 0;
    }

    private int slot(int hash) {
        return hash * 0x9E3779B9 >>> shift;
    }

    private void allocate(int capacity) {
        String[] oldKeys = keys;
        Object[] oldValues = values;
        int[] oldHashes = hashes;
        keys = new String[capacity];
        values = new Object[capacity];
        hashes = new int[capacity];
        shift = 32 - Integer.numberOfTrailingZeros(capacity);
        if (oldKeys == null) {
            return;
        }
        int mask = capacity - 1;
        for (int j = 0; j < oldKeys.length; j++) {
            if (oldKeys[j] != null) {
                int i = slot(oldHashes[j]);
                while (keys[i] != null) {
                    i = i + 1 & mask;
                }
                keys[i] = oldKeys[j];
                values[i] = oldValues[j];
                hashes[i] = oldHashes[j];
            }
        }
    }

    /** The values, in no particular order; the table must not change while they are iterated. */
    @Override public Iterator<V> iterator() {
        return new Iterator<>() {
            private int next = skip(0);

            private int skip(int i) {
                while (i < keys.length && keys[i] == null) {
                    i++;
                }
                return i;
            }

            @Override public boolean hasNext() {
                return next < keys.length;
            }

            @SuppressWarnings("unchecked")
            @Override public V next() {
                if (next >= keys.length) {
                    throw new NoSuchElementException();
                }
                V v = (V) values[next];
                next = skip(next + 1);
                return v;
            }
        };
    }

    @Override public String toString() {
        return "NameTable" + Arrays.toString(Arrays.stream(keys).filter(k -> k != null).toArray());
    }
}
