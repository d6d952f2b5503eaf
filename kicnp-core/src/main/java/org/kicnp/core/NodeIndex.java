package org.kicnp.core;

import java.util.AbstractCollection;
import java.util.Arrays;
import java.util.Collection;
import java.util.Iterator;
import java.util.NoSuchElementException;

/**
 * The knowledge base's name index: frame name to node, iterated in the order names were first added (a node that
 * stays keeps its place), as a {@link java.util.LinkedHashMap} would be. It is probed for every change, most often
 * with a name it does not hold yet (a new frame's), and it holds hundreds of thousands of names, so its lines are
 * never in the cache.
 *
 * <p>A name that ends in {@code -N} (an inference engine names what it derives {@code Frame-N}, with one counter) is
 * kept in a direct-mapped array at index {@code N} modulo its length, found by reading the number off the name: the
 * instances a run derives one after the other sit next to each other, and a new one's name is found free without a
 * probe of a table. Every other name, and a numbered name whose index holds another node, is kept in a hash table;
 * each index counts the names of its number kept there, so a numbered name is looked for in the table only when its
 * index has such names. The array grows with the nodes it holds, not with the numbers.
 *
 * <p>The hash table is open addressing with linear probing, where a probe run reads only the array of hashes (sixteen
 * to a cache line; 0 marks an empty slot, so a stored hash is never 0) and each key sits beside its node, so a miss
 * touches one line and a hit or an insertion two, where a hash map's buckets and entry objects cost a line each and a
 * resize chases every entry. Removal shifts the following entries back (no tombstones).
 *
 * <p>The insertion order is an array of the nodes with holes where nodes were removed, compacted once holes outnumber
 * nodes; each node knows its place ({@link Node#order}). Not thread-safe: the knowledge base guards it with its lock.
 */
final class NodeIndex {
    private static final int MIN_CAPACITY = 16;
    private static final int MIN_NUMBERED = 1024;
    /** Nodes of numbered names, at their number modulo the length. */
    private Node[] numbered = new Node[MIN_NUMBERED];
    /** The number of each node in {@link #numbered}, so that growing re-places them without reading their names. */
    private int[] numbers = new int[MIN_NUMBERED];
    /** For each index of {@link #numbered}, how many names of its number are kept in the hash table. */
    private int[] spilled = new int[MIN_NUMBERED];
    /** Numbered names held: in the array, and in the hash table. */
    private int inArray;
    private int inTable;
    private int[] hashes;
    /** Slot {@code i}'s name at {@code 2i}, its node at {@code 2i + 1}. */
    private Object[] entries;
    private int shift;
    private int size;
    private Node[] order = new Node[16];
    /** Places of {@code order} in use, holes included. */
    private int end;

    NodeIndex() {
        allocate(MIN_CAPACITY);
    }

    int size() {
        return size;
    }

    /** The length of the array of numbered nodes (for tests: it follows the nodes held, not their numbers). */
    int numberedCapacity() {
        return numbered.length;
    }

    boolean containsKey(String name) {
        return get(name) != null;
    }

    Node get(String name) {
        int number = numberOf(name);
        if (number >= 0) {
            int k = number & numbered.length - 1;
            Node at = numbered[k];
            if (at != null && numbers[k] == number && at.name().equals(name)) {
                return at;
            }
            if (spilled[k] == 0) {
                return null;
            }
        }
        int i = slotOf(name, stored(name));
        return hashes[i] == 0 ? null : (Node) entries[2 * i + 1];
    }

    /** Puts a node under a name: at the end of the order, or in the place of the node that name had. */
    void put(String name, Node n) {
        int number = numberOf(name);
        if (number >= 0) {
            int k = number & numbered.length - 1;
            Node at = numbered[k];
            if (at != null && numbers[k] == number && at.name().equals(name)) {
                numbered[k] = n;
                takePlace(at, n);
                return;
            }
            if (at == null && spilled[k] == 0) {
                numbered[k] = n;
                numbers[k] = number;
                inArray++;
                added(n);
                if ((inArray + inTable) * 2 > numbered.length) {
                    growNumbered();
                }
                return;
            }
        }
        int h = stored(name);
        int i = slotOf(name, h);
        if (hashes[i] != 0) {
            Node old = (Node) entries[2 * i + 1];
            entries[2 * i + 1] = n;
            takePlace(old, n);
            return;
        }
        hashes[i] = h;
        entries[2 * i] = name;
        entries[2 * i + 1] = n;
        if (number >= 0) {
            spilled[number & numbered.length - 1]++;
            inTable++;
        }
        added(n);
        if ((size - inArray) * 2 > hashes.length) {
            allocate(hashes.length * 2);
        }
        if (number >= 0 && (inArray + inTable) * 2 > numbered.length) {
            growNumbered();
        }
    }

    /** A name held already keeps its place, with the new node. */
    private void takePlace(Node old, Node n) {
        n.order = old.order;
        order[old.order] = n;
        old.order = -1;
    }

    /** Puts a new node at the end of the order. */
    private void added(Node n) {
        if (end == order.length) {
            if (end - size >= end / 4) {
                compact();
            }
            if (end == order.length) {
                order = Arrays.copyOf(order, order.length * 2);
            }
        }
        n.order = end;
        order[end++] = n;
        size++;
    }

    /** Removes the node of that name; returns it, or null when there was none. */
    Node remove(String name) {
        int number = numberOf(name);
        Node n = null;
        if (number >= 0) {
            int k = number & numbered.length - 1;
            Node at = numbered[k];
            if (at != null && numbers[k] == number && at.name().equals(name)) {
                numbered[k] = null;
                inArray--;
                n = at;
            } else if (spilled[k] == 0) {
                return null;
            }
        }
        if (n == null) {
            int i = slotOf(name, stored(name));
            if (hashes[i] == 0) {
                return null;
            }
            n = (Node) entries[2 * i + 1];
            closeGap(i);
            if (number >= 0) {
                spilled[number & numbered.length - 1]--;
                inTable--;
            }
        }
        size--;
        order[n.order] = null;
        n.order = -1;
        if (size == 0) {
            Arrays.fill(order, 0, end, null);
            end = 0;
        } else if (end > 32 && size < end / 2) {
            compact();
        }
        return n;
    }

    /** The nodes in the order their names were first added: a live view, not to be used while the index changes. */
    Collection<Node> values() {
        return new AbstractCollection<>() {
            @Override public Iterator<Node> iterator() {
                return new Iterator<>() {
                    private int next = skip(0);

                    private int skip(int i) {
                        while (i < end && order[i] == null) {
                            i++;
                        }
                        return i;
                    }

                    @Override public boolean hasNext() {
                        return next < end;
                    }

                    @Override public Node next() {
                        if (next >= end) {
                            throw new NoSuchElementException();
                        }
                        Node n = order[next];
                        next = skip(next + 1);
                        return n;
                    }
                };
            }

            @Override public int size() {
                return size;
            }
        };
    }

    /** Closes the holes in the insertion order, telling each moved node its new place. */
    private void compact() {
        int to = 0;
        for (int i = 0; i < end; i++) {
            Node n = order[i];
            if (n != null) {
                if (to != i) {
                    order[to] = n;
                    n.order = to;
                }
                to++;
            }
        }
        Arrays.fill(order, to, end, null);
        end = to;
    }

    /**
     * Doubles the array of numbered nodes. The nodes in it keep distinct indexes (their numbers differ modulo the old
     * length, so modulo the new one too); the numbered names in the hash table stay there, counted at their new
     * indexes.
     */
    private void growNumbered() {
        Node[] old = numbered;
        int[] oldNumbers = numbers;
        numbered = new Node[old.length * 2];
        numbers = new int[numbered.length];
        spilled = new int[numbered.length];
        int mask = numbered.length - 1;
        for (int i = 0; i < old.length; i++) {
            if (old[i] != null) {
                int k = oldNumbers[i] & mask;
                numbered[k] = old[i];
                numbers[k] = oldNumbers[i];
            }
        }
        if (inTable > 0) {
            for (int i = 0; i < hashes.length; i++) {
                if (hashes[i] != 0) {
                    int number = numberOf((String) entries[2 * i]);
                    if (number >= 0) {
                        spilled[number & mask]++;
                    }
                }
            }
        }
    }

    /**
     * The number a name ends in after its last {@code -}: one to nine digits, with something before the {@code -};
     * -1 for any other name.
     */
    static int numberOf(String name) {
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

    /** The hash kept for a name: its hash code, with 0 (which marks an empty slot) taken as 1. */
    private static int stored(String name) {
        int h = name.hashCode();
        return h == 0 ? 1 : h;
    }

    /** The slot holding {@code name} (of stored hash {@code h}), or the empty slot that ends its probe run. */
    private int slotOf(String name, int h) {
        int mask = hashes.length - 1;
        for (int i = slot(h); ; i = i + 1 & mask) {
            int at = hashes[i];
            if (at == 0) {
                return i;
            }
            if (at == h) {
                Object k = entries[2 * i];
                if (k == name || name.equals(k)) {
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
}
