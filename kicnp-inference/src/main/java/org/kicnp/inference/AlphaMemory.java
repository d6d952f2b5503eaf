package org.kicnp.inference;

import java.util.AbstractCollection;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.function.BiFunction;
import org.kicnp.core.Value;

/**
 * The instances that can fill one slot of one behavior frame (right class, constant conditions hold), with hash
 * indexes on the slot paths that equality joins look up, so a join reads only the partners that can match.
 *
 * <p>The members are the engine's {@link FactView.Fact} records, kept in insertion order in one array: a member's
 * {@link Entry} (held by its fact) knows its position, so adding and removing cost no hashing, and matching meets the
 * facts themselves rather than names to look up. A removed member leaves a hole that iteration skips; the array is
 * compacted once holes outnumber members. Index buckets keep insertion order too, so matching is deterministic.
 * Owned by the engine thread.
 */
final class AlphaMemory {
    private final Rule rule;
    private final SlotPattern pattern;
    private FactView.Fact[] items = new FactView.Fact[8];
    /** Slots of {@code items} in use, holes included. */
    private int end;
    private int size;
    private final List<List<String>> paths = new ArrayList<>(2);
    /** Per path, key → the facts filed under it: a {@link Bag} (insertion order; most keys hold one or two facts). */
    private final List<Map<Value, Object>> indexes = new ArrayList<>(2);
    /** The fact {@link #fileFact} files: set just before each call (one hash look-up per filing, no lambda made). */
    private FactView.Fact filing;
    private final BiFunction<Value, Object, Object> fileFact = (key, bucket) -> Bag.add(bucket, filing);
    /** The join plan of the rule, and this memory's position among its required slots (-1: an optional slot). */
    JoinPlan plan;
    int position = -1;

    /**
     * One fact's membership: where it sits, and the index keys it is filed under (null where a path reached nothing).
     * The keys are one field: the key under the first index itself while no other index has one (most memories have
     * one index, one equality join reading the slot), else a {@code Value[]} by index number. An array per membership
     * was an object per fact and memory, and a field for each form 8 bytes more per membership (32 bytes, not 24).
     */
    static final class Entry {
        final AlphaMemory memory;
        /** The first index's key (a {@link Value} or null) or every index's keys (a {@code Value[]}). */
        private Object keys;
        int at;

        private Entry(AlphaMemory memory, int at) {
            this.memory = memory;
            this.at = at;
        }

        /** The key it is filed under in index {@code index}; null: none. */
        Value key(int index) {
            Object k = keys;
            if (k instanceof Value[] all) {
                return all[index];
            }
            return index == 0 ? (Value) k : null;
        }

        /** Sets the key of index {@code index} of the {@code count} the memory has. */
        void key(int index, Value key, int count) {
            Object k = keys;
            if (k instanceof Value[] all) {
                all[index] = key;
            } else if (index == 0) {
                keys = key;
            } else if (key != null) {
                Value[] all = new Value[count];
                all[0] = (Value) k;
                all[index] = key;
                keys = all;
            }
        }
    }

    AlphaMemory(Rule rule, SlotPattern pattern) {
        this.rule = rule;
        this.pattern = pattern;
    }

    Rule rule() {
        return rule;
    }

    SlotPattern pattern() {
        return pattern;
    }

    /**
     * Indexes the facts by the value each reaches along {@code path} (call before facts are added); returns the
     * index's number for {@link #lookup(int, Value)}. Asking twice for one path gives one index.
     */
    int addIndex(List<String> path) {
        int i = paths.indexOf(path);
        if (i >= 0) {
            return i;
        }
        if (size > 0) {
            throw new IllegalStateException("Indexes are added before facts, not after " + size + " facts.");
        }
        paths.add(List.copyOf(path));
        indexes.add(new HashMap<>());
        return paths.size() - 1;
    }

    boolean contains(FactView.Fact fact) {
        return fact.entryIn(this) != null;
    }

    /** The members in insertion order: a live view, not to be held while the memory changes. */
    Collection<FactView.Fact> facts() {
        return new Members();
    }

    int size() {
        return size;
    }

    /**
     * Adds a fact, indexing it under the value each indexed path reaches from it; returns its membership, for the
     * fact to keep and give back to {@link #remove}; null when the fact was a member already.
     */
    Entry add(FactView.Fact fact, BiFunction<FactView.Fact, List<String>, Value> pathValue) {
        if (fact.entryIn(this) != null) {
            return null;
        }
        if (end == items.length) {
            makeRoom();
        }
        Entry e = new Entry(this, end);
        for (int i = 0, n = paths.size(); i < n; i++) {
            Value key = pathValue.apply(fact, paths.get(i));
            if (key != null) {
                Value k = Values.key(key);
                file(indexes.get(i), k, fact);
                e.key(i, k, n);
            }
        }
        items[end++] = fact;
        size++;
        return e;
    }

    /**
     * Files a member again under the keys its indexed paths reach now (a value it is read through changed without
     * the member being matched again); its place in insertion order stays.
     */
    void rekey(Entry e, BiFunction<FactView.Fact, List<String>, Value> pathValue) {
        FactView.Fact fact = items[e.at];
        if (fact == null || paths.isEmpty()) {
            return;
        }
        for (int i = 0; i < paths.size(); i++) {
            Value was = e.key(i);
            Value reached = pathValue.apply(fact, paths.get(i));
            Value now = reached == null ? null : Values.key(reached);
            if (java.util.Objects.equals(was, now)) {
                continue;
            }
            Map<Value, Object> index = indexes.get(i);
            if (was != null) {
                unfile(index, was, fact);
            }
            if (now != null) {
                file(index, now, fact);
            }
            e.key(i, now, paths.size());
        }
    }

    /** Files a fact under a key (see {@link Bag}). */
    private void file(Map<Value, Object> index, Value key, FactView.Fact fact) {
        filing = fact;
        try {
            index.compute(key, fileFact);
        } finally {
            filing = null;
        }
    }

    /** Takes a fact out of a key's bucket, dropping the bucket once it is empty. */
    private static void unfile(Map<Value, Object> index, Value key, FactView.Fact fact) {
        Object bucket = index.get(key);
        if (bucket != null) {
            Object left = Bag.remove(bucket, fact);
            if (left == null) {
                index.remove(key);
            } else if (left != bucket) {
                index.put(key, left);
            }
        }
    }

    /** Removes a member, given its membership. */
    void remove(Entry e) {
        FactView.Fact fact = items[e.at];
        if (fact == null) {
            return;
        }
        items[e.at] = null;
        size--;
        for (int i = 0, n = paths.size(); i < n; i++) {
            Value key = e.key(i);
            if (key != null) {
                unfile(indexes.get(i), key, fact);
            }
        }
        if (size == 0) {
            Arrays.fill(items, 0, end, null);
            end = 0;
        } else if (end > 32 && size < end / 2) {
            compact();
        }
    }

    /**
     * The facts whose value along index {@code index}'s path has the key {@code key} (see {@link Values#key}), as a
     * {@link Bag} in insertion order (null: none); a live value, not to be held while the memory changes.
     */
    Object bucket(int index, Value key) {
        return indexes.get(index).get(key);
    }

    /**
     * Makes room for up to {@code more} facts about to be offered (a large batch of new instances), so that the member
     * array and each index table grow once instead of step by step: an index is rebuilt at its size after the batch
     * when the batch is larger than what it holds by more than 64 (each key may take several facts, so it may end up
     * roomier than needed). Membership is unchanged.
     */
    void expect(int more) {
        if (end + more > items.length) {
            items = Arrays.copyOf(items, end + more);
        }
        for (int i = 0; i < indexes.size(); i++) {
            Map<Value, Object> index = indexes.get(i);
            if (more > index.size() + 64) {
                Map<Value, Object> bigger = HashMap.newHashMap(index.size() + more);
                bigger.putAll(index);
                indexes.set(i, bigger);
            }
        }
    }

    private void makeRoom() {
        if (end - size >= end / 4 && end > size) {
            compact();
        }
        if (end == items.length) {
            items = Arrays.copyOf(items, items.length + (items.length >> 1) + 2);
        }
    }

    /** Closes the holes, telling each moved member its new position. */
    private void compact() {
        int to = 0;
        for (int i = 0; i < end; i++) {
            FactView.Fact f = items[i];
            if (f != null) {
                if (to != i) {
                    items[to] = f;
                    f.entryIn(this).at = to;
                }
                to++;
            }
        }
        Arrays.fill(items, to, end, null);
        end = to;
    }

    /** The members, skipping holes. */
    private final class Members extends AbstractCollection<FactView.Fact> {
        @Override public Iterator<FactView.Fact> iterator() {
            return new Iterator<>() {
                private int next = skip(0);

                private int skip(int i) {
                    while (i < end && items[i] == null) {
                        i++;
                    }
                    return i;
                }

                @Override public boolean hasNext() {
                    return next < end;
                }

                @Override public FactView.Fact next() {
                    if (next >= end) {
                        throw new NoSuchElementException();
                    }
                    FactView.Fact f = items[next];
                    next = skip(next + 1);
                    return f;
                }
            };
        }

        @Override public int size() {
            return size;
        }
    }
}
