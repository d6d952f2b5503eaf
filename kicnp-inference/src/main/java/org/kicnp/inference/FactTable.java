package org.kicnp.inference;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import org.kicnp.core.NameTable;

/**
 * The engine's fact records by instance name. A name that ends in {@code -N} (the engine names what it derives
 * {@code Frame-N}, with one counter) is kept in a direct-mapped array at index {@code N} modulo its length, reached by
 * reading the number off the name: a firing's new instance is stored next to the one made before it instead of at a
 * random slot of a hash table whose lines are never in the cache. Every other name, and a numbered name whose index
 * holds another name, is kept in a {@link NameTable}; each index counts the names of its number kept there, so a
 * numbered name is looked for in the table only when its index has such names. The array grows with the facts it
 * holds, not with the numbers: a long run that retracts what it derived keeps it small. It grows only when a number
 * finds its index taken while the array is half full or more, so numbers given out one after the other fill it to the
 * last place before it first doubles. Not thread-safe: owned by the engine thread.
 */
final class FactTable implements Iterable<FactView.Fact> {
    private static final int MIN_CAPACITY = 1024;
    private FactView.Fact[] numbered = new FactView.Fact[MIN_CAPACITY];
    /** The number of each fact in {@link #numbered}, so that growing re-places them without reading their names. */
    private int[] numbers = new int[MIN_CAPACITY];
    /** For each index of {@link #numbered}, how many names of its number are kept in {@link #others}. */
    private int[] spilled = new int[MIN_CAPACITY];
    private int mask = MIN_CAPACITY - 1;
    /** Numbered names held: in the array, and in the table. */
    private int inArray;
    private int inOthers;
    private final NameTable<FactView.Fact> others = new NameTable<>();
    private int size;

    int size() {
        return size;
    }

    /** The length of the array of numbered facts (for tests: it follows the facts held, not their numbers). */
    int capacity() {
        return numbered.length;
    }

    /** The fact of that name, made (without a frame) and stored when there is none yet. */
    FactView.Fact touch(String name) {
        return touch(name, NameTable.numberOf(name));
    }

    /** As {@link #touch(String)}, with the name's {@link NameTable#numberOf number} known to the caller. */
    FactView.Fact touch(String name, int n) {
        if (n < 0) {
            int before = others.size();
            FactView.Fact f = others.computeIfAbsent(name, FactView.Fact::new);
            size += others.size() - before;
            return f;
        }
        int i = n & mask;
        FactView.Fact at = numbered[i];
        if (at != null && numbers[i] == n && at.name.equals(name)) {
            return at;
        }
        if (spilled[i] > 0) {
            FactView.Fact f = others.get(name);
            if (f != null) {
                return f;
            }
        }
        FactView.Fact f = new FactView.Fact(name);
        size++;
        if (at != null && (inArray + inOthers) * 2 >= numbered.length) {
            // Another number holds its index and the array is half full: grow it, then place the fact there.
            grow();
            i = n & mask;
            at = numbered[i];
        }
        if (at == null) {
            numbered[i] = f;
            numbers[i] = n;
            inArray++;
        } else {
            others.computeIfAbsent(name, k -> f);
            spilled[i]++;
            inOthers++;
        }
        return f;
    }

    /**
     * Makes room for a batch of new names ({@code hashed} that do not end in a number, {@code numbered} that do), so
     * that each structure grows once, to its size after the batch, instead of step by step while it goes in.
     */
    void ensureRoom(int hashed, int numbered) {
        if (hashed < 0 || numbered < 0) {
            throw new IllegalArgumentException("Room for " + hashed + " and " + numbered + " names?");
        }
        if (hashed > 0) {
            others.ensureCapacity(others.size() + hashed);
        }
        int length = this.numbered.length;
        while ((long) (inArray + inOthers + numbered) * 2 > length && length < 1 << 30) {
            length <<= 1;
        }
        if (length > this.numbered.length) {
            grow(length);
        }
    }

    /** The fact of that name, or null. */
    FactView.Fact get(String name) {
        int n = NameTable.numberOf(name);
        if (n < 0) {
            return others.get(name);
        }
        int i = n & mask;
        FactView.Fact at = numbered[i];
        if (at != null && numbers[i] == n && at.name.equals(name)) {
            return at;
        }
        return spilled[i] > 0 ? others.get(name) : null;
    }

    /** Removes the fact of that name; returns it, or null when there was none. */
    FactView.Fact remove(String name) {
        int n = NameTable.numberOf(name);
        if (n < 0) {
            FactView.Fact f = others.remove(name);
            if (f != null) {
                size--;
            }
            return f;
        }
        int i = n & mask;
        FactView.Fact at = numbered[i];
        if (at != null && numbers[i] == n && at.name.equals(name)) {
            numbered[i] = null;
            inArray--;
            size--;
            return at;
        }
        if (spilled[i] == 0) {
            return null;
        }
        FactView.Fact f = others.remove(name);
        if (f != null) {
            spilled[i]--;
            inOthers--;
            size--;
        }
        return f;
    }

    /**
     * Doubles the array. The facts in it keep distinct indexes (their numbers differ modulo the old length, so modulo
     * the new one too); the numbered names in the table stay there, counted at their new indexes.
     */
    private void grow() {
        grow(numbered.length * 2);
    }

    /** Re-places the numbered facts in an array of {@code length} (a power of two, larger than the one in use). */
    private void grow(int length) {
        FactView.Fact[] old = numbered;
        int[] oldNumbers = numbers;
        numbered = new FactView.Fact[length];
        numbers = new int[numbered.length];
        spilled = new int[numbered.length];
        mask = numbered.length - 1;
        for (int i = 0; i < old.length; i++) {
            if (old[i] != null) {
                int k = oldNumbers[i] & mask;
                numbered[k] = old[i];
                numbers[k] = oldNumbers[i];
            }
        }
        if (inOthers > 0) {
            for (FactView.Fact f : others) {
                int n = NameTable.numberOf(f.name);
                if (n >= 0) {
                    spilled[n & mask]++;
                }
            }
        }
    }

    /** The facts, in no particular order (a copy). */
    @Override public Iterator<FactView.Fact> iterator() {
        List<FactView.Fact> all = new ArrayList<>(size);
        for (FactView.Fact f : numbered) {
            if (f != null) {
                all.add(f);
            }
        }
        for (FactView.Fact f : others) {
            all.add(f);
        }
        return all.iterator();
    }
}
