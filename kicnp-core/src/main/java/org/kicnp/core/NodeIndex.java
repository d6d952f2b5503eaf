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
 * index has such names. The array grows with the nodes it holds, not with the numbers, and only when a number finds
 * its index taken while the array is half full or more: numbers given out one after the other fill it to the last
 * place before it first doubles.
 *
 * <p>The hash table is a {@link NameTable}: a probe run reads only an array of hashes and each name sits beside its
 * node, so a miss touches one cache line and a hit or an insertion two, where a hash map's buckets and entry objects
 * cost a line each and a resize chases every entry.
 *
 * <p>The insertion order is an array of the nodes with holes where nodes were removed, compacted once holes outnumber
 * nodes; each node knows its place ({@link Node#order}). Not thread-safe: the knowledge base guards it with its lock.
 */
final class NodeIndex {
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
    /** Every other name, and numbered names whose index holds another node. */
    private final NameTable<Node> table = new NameTable<>();
    private int size;
    private Node[] order = new Node[16];
    /** Places of {@code order} in use, holes included. */
    private int end;

    int size() {
        return size;
    }

    /** The length of the array of numbered nodes (for tests: it follows the nodes held, not their numbers). */
    int numberedCapacity() {
        return numbered.length;
    }

    /** The slots of the hash table of other names (for tests, as {@link #numberedCapacity}). */
    int tableCapacity() {
        return table.capacity();
    }

    boolean containsKey(String name) {
        return get(name) != null;
    }

    Node get(String name) {
        return get(name, NameTable.numberOf(name));
    }

    /**
     * As {@link #get(String)}, given the name's {@linkplain NameTable#numberOf number}: a caller that needs it twice
     * (a look-up, then a put) reads it once.
     */
    Node get(String name, int number) {
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
        return table.get(name);
    }

    /** Puts a node under a name: at the end of the order, or in the place of the node that name had. */
    void put(String name, Node n) {
        place(name, NameTable.numberOf(name), n, true);
    }

    /**
     * Puts a node under a name the index does not hold, at the end of the order; answers false, changing nothing,
     * when it holds the name. The look-up and the put are one probe: a batch of new names asks for each one once.
     */
    boolean putNew(String name, int number, Node n) {
        return place(name, number, n, false) == null;
    }

    /**
     * Puts a node under a name, in the place of the node that name had ({@code replace}) or, when the name is held and
     * not {@code replace}, not at all; answers the node the name had, or null for a new name (put at the end of the
     * order).
     */
    private Node place(String name, int number, Node n, boolean replace) {
        if (number >= 0) {
            int k = number & numbered.length - 1;
            Node at = numbered[k];
            if (at != null && numbers[k] == number && at.name().equals(name)) {
                if (replace) {
                    numbered[k] = n;
                    takePlace(at, n);
                }
                return at;
            }
            if (at == null && spilled[k] == 0) {
                numbered[k] = n;
                numbers[k] = number;
                inArray++;
                added(n);
                return null;
            }
            if (at != null && (inArray + inTable) * 2 >= numbered.length) {
                // Another number holds its index and the array is half full: grow it (this name is not held, or it
                // would have been at its index or counted as spilled there), then put the name in the larger one.
                growNumbered();
                return place(name, number, n, replace);
            }
        }
        Node old = replace ? table.put(name, n) : table.putIfAbsent(name, n);
        if (old != null) {
            if (replace) {
                takePlace(old, n);
            }
            return old;
        }
        if (number >= 0) {
            spilled[number & numbered.length - 1]++;
            inTable++;
        }
        added(n);
        return null;
    }

    /**
     * Makes room for a batch of new names before it is put in: {@code hashed} names that do not end in a number and
     * {@code numbered} that do. Each structure grows at most once, to its size after the batch, instead of doubling
     * step by step (re-placing every name it holds at each step) while the batch goes in.
     */
    void ensureRoom(int hashed, int numbered) {
        if (hashed < 0 || numbered < 0) {
            throw new IllegalArgumentException("Room for " + hashed + " and " + numbered + " names?");
        }
        if (hashed > 0) {
            table.ensureCapacity(table.size() + hashed);
        }
        long need = (long) end + hashed + numbered;
        if (need > order.length) {
            order = Arrays.copyOf(order, (int) Math.min(Integer.MAX_VALUE - 8, Math.max(need, 2L * order.length)));
        }
        int length = this.numbered.length;
        while ((long) (inArray + inTable + numbered) * 2 > length && length < 1 << 30) {
            length <<= 1;
        }
        if (length > this.numbered.length) {
            growNumbered(length);
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
        int number = NameTable.numberOf(name);
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
            n = table.remove(name);
            if (n == null) {
                return null;
            }
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
     * length, so modulo any larger power of two too); the numbered names in the hash table stay there, counted at
     * their new indexes.
     */
    private void growNumbered() {
        growNumbered(numbered.length * 2);
    }

    /** Re-places the numbered nodes in an array of {@code length} (a power of two, larger than the one in use). */
    private void growNumbered(int length) {
        Node[] old = numbered;
        int[] oldNumbers = numbers;
        numbered = new Node[length];
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
            table.forEachKey(name -> {
                int number = NameTable.numberOf(name);
                if (number >= 0) {
                    spilled[number & mask]++;
                }
            });
        }
    }
}
