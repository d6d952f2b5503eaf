package org.kicnp.core;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.NoSuchElementException;
import java.util.function.Consumer;
import java.util.function.Function;

/**
 * A map from frame names to values in flat arrays, open addressing with linear probing: the knowledge base's name
 * index ({@code NodeIndex}) and the inference engine's fact records are built on it. Both look names up for every
 * change and grow by the hundred thousand within one run, so the cost of a probe is the cache lines it touches: a probe run reads only the array of hashes (sixteen to a cache line;
 * an empty slot holds 0, so a stored hash is never 0), and each key sits beside its value in one array, so a hit or a
 * new entry touches two lines of a table whose lines are never in the cache, where a key array, a value array and a
 * hash array touched three (a {@link java.util.HashMap} chases one entry object per name besides). Removal shifts
 * the following entries back, so there are no tombstones. Null keys and values are not allowed. Not thread-safe: its
 * owner guards it (the knowledge base's lock, the engine's thread).
 *
 * @param <V> the record type
 */
public final class NameTable<V> implements Iterable<V> {
    private static final int MIN_CAPACITY = 16;
    /** The stored hash of each slot ({@link #stored}); 0: the slot is empty. */
    private int[] hashes;
    /** Slot {@code i}'s key at {@code 2i}, its value at {@code 2i + 1}. */
    private Object[] entries;
    private int size;
    private int shift;

    public NameTable() {
        allocate(MIN_CAPACITY);
    }

    /** An empty table with room for {@code expected} names before it first grows. */
    public NameTable(int expected) {
        allocate(capacityFor(expected));
    }

    /**
     * Makes room for {@code expected} names in all before the table next grows: a caller about to put a batch of
     * names in (a knowledge base's batch of instances, an engine's batch of events) grows the table once, instead
     * of doubling it step by step and re-placing every name at each step.
     */
    public void ensureCapacity(int expected) {
        int capacity = capacityFor(expected);
        if (capacity > hashes.length) {
            allocate(capacity);
        }
    }

    /** The least capacity that holds {@code expected} names at most half full. */
    private static int capacityFor(int expected) {
        if (expected < 0 || expected > 1 << 29) {
            throw new IllegalArgumentException("A name table holds 0 to 2^29 names, not " + expected + ".");
        }
        int capacity = MIN_CAPACITY;
        while (capacity < 2 * expected) {
            capacity <<= 1;
        }
        return capacity;
    }

    public int size() {
        return size;
    }

    /** The slots of the table (for tests: it holds this many names at most half full before it grows). */
    int capacity() {
        return hashes.length;
    }

    @SuppressWarnings("unchecked")
    public V get(String key) {
        int i = slotOf(key, stored(key));
        return hashes[i] == 0 ? null : (V) entries[2 * i + 1];
    }

    /** The value of {@code key}, made by {@code make} and stored when there is none (one probe sequence either way). */
    @SuppressWarnings("unchecked")
    public V computeIfAbsent(String key, Function<String, V> make) {
        int h = stored(key);
        int i = slotOf(key, h);
        if (hashes[i] != 0) {
            return (V) entries[2 * i + 1];
        }
        V v = make.apply(key);
        insert(i, h, key, v);
        return v;
    }

    /** Puts {@code value} under {@code key}; returns the value it replaced, or null when there was none. */
    @SuppressWarnings("unchecked")
    public V put(String key, V value) {
        int h = stored(key);
        int i = slotOf(key, h);
        if (hashes[i] != 0) {
            V old = (V) entries[2 * i + 1];
            entries[2 * i + 1] = value;
            return old;
        }
        insert(i, h, key, value);
        return null;
    }

    /**
     * Puts {@code value} under {@code key} unless the key is held; returns the value held, or null when it put this
     * one (one probe sequence either way).
     */
    @SuppressWarnings("unchecked")
    public V putIfAbsent(String key, V value) {
        int h = stored(key);
        int i = slotOf(key, h);
        if (hashes[i] != 0) {
            return (V) entries[2 * i + 1];
        }
        insert(i, h, key, value);
        return null;
    }

    /** Fills the empty slot {@code i} (the end of the key's probe run) and grows the table when half full. */
    private void insert(int i, int h, String key, V value) {
        hashes[i] = h;
        entries[2 * i] = key;
        entries[2 * i + 1] = value;
        if (++size * 2 > hashes.length) {
            allocate(hashes.length * 2);
        }
    }

    /** Calls {@code action} with every key, in no particular order; the table must not change meanwhile. */
    public void forEachKey(Consumer<String> action) {
        for (int i = 0; i < hashes.length; i++) {
            if (hashes[i] != 0) {
                action.accept((String) entries[2 * i]);
            }
        }
    }

    /** Removes the entry of {@code key}; returns its value, or null when there was none. */
    @SuppressWarnings("unchecked")
    public V remove(String key) {
        int i = slotOf(key, stored(key));
        if (hashes[i] == 0) {
            return null;
        }
        V old = (V) entries[2 * i + 1];
        size--;
        closeGap(i);
        return old;
    }

    /**
     * The number a name ends in after its last {@code -}: one to nine digits, with something before the {@code -};
     * -1 for any other name. An inference engine names what it derives {@code Frame-N} with one counter, so the
     * indexes of such names ({@code NodeIndex}, the engine's fact records) keep them in arrays by this number.
     */
    public static int numberOf(String name) {
        int end = name.length();
        int n = 0;
        int scale = 1;
        for (int i = end - 1; i >= 0; i--) {
            char c = name.charAt(i);
            if (c == '-') {
                return i > 0 && i < end - 1 ? n : -1;
            }
            if (c < '0' || c > '9' || end - i > 9) {
                return -1;
            }
            n += (c - '0') * scale;
            scale *= 10;
        }
        return -1;
    }

    /** {@link #numberOf(String)} of the frame's name, worked out once per frame object and then read from it. */
    public static int numberOf(Frame frame) {
        int kept = frame.nameNumber;
        if (kept == 0) {
            kept = numberOf(frame.name()) + 2;
            frame.nameNumber = kept;
        }
        return kept - 2;
    }

    /** Keeps in a new frame the {@link #numberOf(String) number} of its name, known to the caller. */
    static void keepNumber(Frame frame, int number) {
        frame.nameNumber = number + 2;
    }

    /** The hash kept for {@code key}: its hash code, with 0 (which marks an empty slot) taken as 1. */
    private static int stored(String key) {
        int h = key.hashCode();
        return h == 0 ? 1 : h;
    }

    /** The slot holding {@code key} (of stored hash {@code h}), or the empty slot that ends its probe run. */
    private int slotOf(String key, int h) {
        int mask = hashes.length - 1;
        for (int i = slot(h); ; i = i + 1 & mask) {
            int at = hashes[i];
            if (at == 0) {
                return i;
            }
            if (at == h) {
                Object k = entries[2 * i];
                if (k == key || key.equals(k)) {
                    return i;
                }
            }
        }
    }

    /** Backward-shift deletion: moves later entries of the probe run into the gap at {@code gap}. */
    private void closeGap(int gap) {
        int mask = hashes.length - 1;
        int i = gap;
        while (true) {
            i = i + 1 & mask;
            if (hashes[i] == 0) {
                break;
            }
            int home = slot(hashes[i]);
            // The entry at i may move to the gap when its home is not in the cyclic range (gap, i].
            boolean movable = gap <= i ? home <= gap || home > i : home <= gap && home > i;
            if (movable) {
                hashes[gap] = hashes[i];
                entries[2 * gap] = entries[2 * i];
                entries[2 * gap + 1] = entries[2 * i + 1];
                gap = i;
            }
        }
        hashes[gap] = 0;
        entries[2 * gap] = null;
        entries[2 * gap + 1] = null;
    }

    private int slot(int hash) {
        return hash * 0x9E3779B9 >>> shift;
    }

    private void allocate(int capacity) {
        int[] oldHashes = hashes;
        Object[] oldEntries = entries;
        hashes = new int[capacity];
        entries = new Object[2 * capacity];
        shift = 32 - Integer.numberOfTrailingZeros(capacity);
        if (oldHashes == null) {
            return;
        }
        int mask = capacity - 1;
        for (int j = 0; j < oldHashes.length; j++) {
            int h = oldHashes[j];
            if (h != 0) {
                int i = slot(h);
                while (hashes[i] != 0) {
                    i = i + 1 & mask;
                }
                hashes[i] = h;
                entries[2 * i] = oldEntries[2 * j];
                entries[2 * i + 1] = oldEntries[2 * j + 1];
            }
        }
    }

    /** The values, in no particular order; the table must not change while they are iterated. */
    @Override public Iterator<V> iterator() {
        return new Iterator<>() {
            private int next = skip(0);

            private int skip(int i) {
                while (i < hashes.length && hashes[i] == 0) {
                    i++;
                }
                return i;
            }

            @Override public boolean hasNext() {
                return next < hashes.length;
            }

            @SuppressWarnings("unchecked")
            @Override public V next() {
                if (next >= hashes.length) {
                    throw new NoSuchElementException();
                }
                V v = (V) entries[2 * next + 1];
                next = skip(next + 1);
                return v;
            }
        };
    }

    @Override public String toString() {
        List<Object> keys = new ArrayList<>(size);
        for (int i = 0; i < hashes.length; i++) {
            if (hashes[i] != 0) {
                keys.add(entries[2 * i]);
            }
        }
        return "NameTable" + keys;
    }
}
