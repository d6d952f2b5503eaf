package org.kicnp.core;

import java.util.Arrays;
import java.util.Iterator;
import java.util.NoSuchElementException;

/**
 * An insertion-ordered set of nodes, for the knowledge base's derived indexes: a class's children, every instance
 * below a class, the frames that refer to a frame. An instance sits in the set of each of its ancestors, and a class
 * high up holds hundreds of thousands, so members are kept in one array (plus, past a few members, an
 * open-addressing table of their positions, made on first use) instead of a {@link java.util.LinkedHashSet}'s entry objects: about a
 * third of the memory and no allocation per member, with O(1) add, remove and contains. A removed member leaves a hole
 * that iteration skips; the array is compacted once holes outnumber members. Members are compared by identity.
 * Changed only under the knowledge base's write lock.
 */
final class NodeSet implements Iterable<Node> {
    /** Up to this many slots the set is searched linearly and has no table. */
    private static final int LINEAR = 8;

    private Node[] items;
    /** Slots of {@code items} in use, holes included. */
    private int end;
    private int size;
    /**
     * Position + 1 of each member, by hash, linear probing; 0 is empty. Null while {@code end <= LINEAR}, and built
     * only when a membership question is first asked: a set that is only added to (a class's instances while they
     * are asserted) never pays for it.
     */
    private int[] table;
    private int shift;

    NodeSet(int capacity) {
        items = new Node[Math.max(2, capacity)];
    }

    int size() {
        return size;
    }

    boolean isEmpty() {
        return size == 0;
    }

    boolean contains(Node n) {
        return indexOf(n) >= 0;
    }

    /** Adds the node at the end unless it is a member already; answers whether it was added. */
    boolean add(Node n) {
        if (indexOf(n) >= 0) {
            return false;
        }
        append(n);
        return true;
    }

    /**
     * Adds a node the caller knows is not a member (a node made by this very batch), without the membership probe
     * that {@link #add} pays.
     */
    void addNew(Node n) {
        append(n);
    }

    private void append(Node n) {
        if (end == items.length) {
            makeRoom();
        }
        items[end] = n;
        if (table != null) {
            place(n, end);
        }
        end++;
        size++;
        if (table != null && end * 2 > table.length) {
            rebuildTable();
        }
    }

    boolean remove(Node n) {
        int at = indexOf(n);
        if (at < 0) {
            return false;
        }
        // The table keeps pointing at the hole, which matches nothing, so probing past it still works.
        items[at] = null;
        size--;
        if (size == 0) {
            Arrays.fill(items, 0, end, null);
            end = 0;
            table = null;
        } else if (end > LINEAR * 2 && size < end / 2) {
            compact();
        }
        return true;
    }

    /** Removes every member of {@code other}. */
    void removeAll(NodeSet other) {
        for (Node n : other) {
            remove(n);
        }
    }

    @Override public Iterator<Node> iterator() {
        return new Iterator<>() {
            private int next = skipHoles(0);

            @Override public boolean hasNext() {
                return next < end;
            }

            @Override public Node next() {
                if (next >= end) {
                    throw new NoSuchElementException();
                }
                Node n = items[next];
                next = skipHoles(next + 1);
                return n;
            }
        };
    }

    private int skipHoles(int from) {
        int i = from;
        while (i < end && items[i] == null) {
            i++;
        }
        return i;
    }

    private int indexOf(Node n) {
        if (table == null && end > LINEAR) {
            rebuildTable();
        }
        if (table == null) {
            for (int i = 0; i < end; i++) {
                if (items[i] == n) {
                    return i;
                }
            }
            return -1;
        }
        int mask = table.length - 1;
        for (int slot = slotOf(n); ; slot = slot + 1 & mask) {
            int p = table[slot];
            if (p == 0) {
                return -1;
            }
            if (items[p - 1] == n) {
                return p - 1;
            }
        }
    }

    /**
     * A member's slot, from its name's hash: worked out here, not kept in each node when made, since most nodes (a
     * firing's new instance, named a moment ago) are never in a set with a table. The name keeps its hash.
     */
    private int slotOf(Node n) {
        return n.name().hashCode() * 0x9E3779B9 >>> shift;
    }

    private void place(Node n, int position) {
        int mask = table.length - 1;
        int slot = slotOf(n);
        while (table[slot] != 0) {
            slot = slot + 1 & mask;
        }
        table[slot] = position + 1;
    }

    /**
     * Grows the array, or compacts it when a quarter or more of it is holes. It doubles: a class's set grows by the
     * thousand within one batch or run of the engine, and doubling copies each member about once on the way where
     * growing by half copied it about twice (and made twice as many arrays); the unused end of a set that only grows is
     * at most half its array, one reference a place.
     */
    private void makeRoom() {
        int holes = end - size;
        if (holes > 0 && holes >= end / 4) {
            compact();
        }
        if (end == items.length) {
            items = Arrays.copyOf(items, items.length * 2);
        }
    }

    private void compact() {
        int to = 0;
        for (int i = 0; i < end; i++) {
            if (items[i] != null) {
                items[to++] = items[i];
            }
        }
        Arrays.fill(items, to, end, null);
        end = to;
        if (items.length > 64 && items.length > end * 3) {
            items = Arrays.copyOf(items, end + (end >> 1) + 2);
        }
        table = null; // positions moved: made again when next asked
    }

    /** A table at most a quarter full, so it is rebuilt only after the members have doubled. */
    private void rebuildTable() {
        if (end <= LINEAR) {
            table = null;
            return;
        }
        int bits = 32 - Integer.numberOfLeadingZeros(end * 4 - 1);
        table = new int[1 << bits];
        shift = 32 - bits;
        for (int i = 0; i < end; i++) {
            if (items[i] != null) {
                place(items[i], i);
            }
        }
    }
}
