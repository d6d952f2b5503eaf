package org.kicnp.inference;

import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.NameTable;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * The instances as the engine has seen them, one {@link Fact} each: its frame as of the last knowledge base event the
 * engine processed, and the engine's own records about it (assertion stamp, the memories it is in, the activations
 * and fired bindings it takes part in), kept together so that an event costs one look-up by name instead of one per
 * record. Matching reads slot values here, without the knowledge base's lock, and sees the state its memories were
 * built from. A slot the instance does not hold itself (an inherited value or default) is read from the knowledge
 * base. Owned by the engine thread.
 */
final class FactView implements Conditions.Reader {
    private final KnowledgeBase kb;
    private final FactTable facts = new FactTable();

    /** The stamp of a fact that has left the view ({@link Fact#gone}). */
    static final long GONE = Long.MIN_VALUE;

    /** What the engine knows of one instance. Fields are null until needed. */
    static final class Fact {
        final String name;
        /**
         * The frame as last seen; null when the network met the instance in the knowledge base before its event. Set
         * through {@link #seen}, which keeps {@link #links} true to it.
         */
        Frame frame;
        /** When the engine asserted it (recency); {@link #GONE} once it has left the view. */
        long stamp;
        /**
         * The fact's memberships of alpha memories: null (none), one {@link AlphaMemory.Entry} (most facts: one
         * memory takes their class), or an array of exactly as many as it has.
         */
        private Object entries;
        /** The activations that bind it waiting on the agenda: a {@link Bag}. */
        Object activations;
        /** The bindings with this fact that have fired (refraction), {@link BindingKey}s: a {@link Bag}. */
        Object fired;
        /** How the engine derived this instance, if it did. */
        Derivation derivation;
        /** The derived instances that rest on this one, in the order they were made: a {@link Bag} of names. */
        Object dependents;
        /**
         * The facts the slots of {@link #frame} refer to, by the slot's position in it (null: not resolved yet); let
         * go whenever the frame is replaced by another, so it never needs the frame it was made for beside it. A firing
         * sets it before the engine has seen its instance's frame ({@link #frame} still null), for that very frame.
         * Lets a path step from fact to fact without looking the next name up again ({@link FactView#follow}).
         */
        Fact[] links;
        /** A reference to this fact, made once for the slots of every instance derived from it; null until needed. */
        private Value ref;

        Fact(String name) {
            this.name = name;
        }

        /** The frame the instance has now (added or replaced); links made for another frame are let go. */
        void seen(Frame now) {
            if (frame != now && frame != null) {
                links = null;
            }
            frame = now;
        }

        /**
         * Whether the fact has left the view: a link to it is stale (its name may come back as another fact). Kept in
         * the stamp, which a fact that left never takes again, rather than in a field of its own: one field fewer
         * makes a record 56 bytes instead of 64.
         */
        boolean gone() {
            return stamp == GONE;
        }

        /** A reference to this fact ({@code Value.ref(name)}), the same one each time. */
        Value ref() {
            if (ref == null) {
                ref = Value.ref(name);
            }
            return ref;
        }

        /** The fact's membership of memory {@code m}, or null. */
        AlphaMemory.Entry entryIn(AlphaMemory m) {
            if (entries instanceof AlphaMemory.Entry e) {
                return e.memory == m ? e : null;
            }
            if (entries != null) {
                for (AlphaMemory.Entry e : (AlphaMemory.Entry[]) entries) {
                    if (e.memory == m) {
                        return e;
                    }
                }
            }
            return null;
        }

        void enter(AlphaMemory.Entry e) {
            if (entries == null) {
                entries = e;
            } else {
                AlphaMemory.Entry[] in = entryArray();
                AlphaMemory.Entry[] more = Arrays.copyOf(in, in.length + 1);
                more[in.length] = e;
                entries = more;
            }
        }

        /** The memberships as an array (a new one for a single membership); null for none. */
        private AlphaMemory.Entry[] entryArray() {
            return entries instanceof AlphaMemory.Entry e ? new AlphaMemory.Entry[] {e} : (AlphaMemory.Entry[]) entries;
        }

        /** Forgets one memory (a rule was removed); the memory itself is dropped by the caller. */
        void leave(AlphaMemory m) {
            if (entries == null) {
                return;
            }
            AlphaMemory.Entry[] kept = Arrays.stream(entryArray()).filter(e -> e.memory != m)
                    .toArray(AlphaMemory.Entry[]::new);
            entries = kept.length == 0 ? null : kept.length == 1 ? kept[0] : kept;
        }

        /** Takes the fact out of every memory it is in. */
        void leaveAll() {
            if (entries == null) {
                return;
            }
            AlphaMemory.Entry[] in = entryArray();
            entries = null;
            for (AlphaMemory.Entry e : in) {
                e.memory.remove(e);
            }
        }

        void activation(Activation a) {
            activations = Bag.add(activations, a);
        }

        /** The activations that bind it, in the order they were made (a copy). */
        List<Activation> activations() {
            return Bag.toList(activations);
        }

        void dependent(String instance) {
            dependents = Bag.addIfAbsent(dependents, instance);
        }

        /**
         * As {@link #dependent}, for an instance a firing has just named: its name comes from the engine's counter and
         * was never used, and a binding holds each fact once, so the look-up for it in the list is skipped.
         */
        void newDependent(String instance) {
            dependents = Bag.add(dependents, instance);
        }

        /** The derived instances that rest on it, in the order they were made (a copy). */
        List<String> dependents() {
            return Bag.toList(dependents);
        }

        void fired(BindingKey k) {
            fired = Bag.addIfAbsent(fired, k);
        }

        /** {@link #fired}, for a binding that has just fired: its key is in no fact's list yet, so no search. */
        void firedNow(BindingKey k) {
            fired = Bag.add(fired, k);
        }

        boolean hasFired(BindingKey k) {
            return Bag.contains(fired, k);
        }

        void unfire(BindingKey k) {
            fired = Bag.remove(fired, k);
        }
    }

    FactView(KnowledgeBase kb) {
        this.kb = kb;
    }

    /** Records the instance's frame (as added or replaced) and returns its fact. */
    Fact put(Frame instance) {
        Fact f = touch(instance.name());
        f.seen(instance);
        return f;
    }

    /** Makes room for a batch of new instances' names ({@link FactTable#ensureRoom}). */
    void ensureRoom(int hashed, int numbered) {
        facts.ensureRoom(hashed, numbered);
    }

    /** The fact of that name, made (without a frame) when there is none yet. */
    Fact touch(String name) {
        return facts.touch(name);
    }

    /** As {@link #touch(String)}, with the name's {@link NameTable#numberOf number} known to the caller. */
    Fact touch(String name, int number) {
        return facts.touch(name, number);
    }

    /** The fact of that name, or null. */
    Fact get(String name) {
        return facts.get(name);
    }

    void remove(String name) {
        Fact f = facts.remove(name);
        if (f != null) {
            f.stamp = GONE;
        }
    }

    /** The assertion stamp of an instance; 0 when the engine has not stamped it. */
    long stamp(String name) {
        Fact f = facts.get(name);
        return f == null ? 0L : f.stamp;
    }

    /** Every fact (for the rare whole-engine operations). */
    Iterable<Fact> all() {
        return facts;
    }

    @Override public Optional<Value> value(String frame, String slot) {
        return value(facts.get(frame), frame, slot);
    }

    /**
     * The value {@code path} reaches from a fact: what {@link Conditions#follow(Value, List)} reads from
     * {@code Value.ref(fact.name)}. A step through a reference the fact's frame holds itself goes to the referred
     * fact's record directly, resolved by name once per frame ({@link Fact#links}); any other step (an inherited
     * value, a fact not in the view, a path longer than {@link Conditions#follow} reads) is read as that method reads
     * it.
     */
    Optional<Value> follow(Fact fact, List<String> path, Conditions conditions) {
        return Optional.ofNullable(followOrNull(fact, path, conditions));
    }

    /**
     * {@link #follow}, or null where it is empty: matching follows an index path for every fact it files and every
     * join it looks up, and an Optional per step would be garbage on that path.
     */
    Value followOrNull(Fact fact, List<String> path, Conditions conditions) {
        int n = path.size();
        if (n == 0) {
            return Value.ref(fact.name);
        }
        if (n > Conditions.MAX_PATH) {
            Value first = valueOrNull(fact, fact.name, path.getFirst());
            return first == null ? null : conditions.follow(first, path, 1).orElse(null);
        }
        Fact cur = fact;
        for (int i = 0; i < n - 1; i++) {
            Fact next = linked(cur, path.get(i));
            if (next == null) {
                Value v = valueOrNull(cur, cur.name, path.get(i));
                return v == null ? null : conditions.follow(v, path, i + 1).orElse(null);
            }
            cur = next;
        }
        return valueOrNull(cur, cur.name, path.get(n - 1));
    }

    /**
     * The record of the instance that {@code slot}, held by the fact's own frame, refers to: the fact the view has
     * under that name, from {@link Fact#links} when resolved before for this frame. Null when the slot is not the
     * frame's own with a value, its value is not a reference, or the view has no fact of that name (the caller then
     * reads the step by name).
     */
    private Fact linked(Fact f, String slot) {
        Frame frame = f.frame;
        if (frame == null) {
            return null;
        }
        List<Slot> slots = frame.slots();
        for (int j = 0; j < slots.size(); j++) {
            Slot s = slots.get(j);
            if (!s.name().equals(slot)) {
                continue;
            }
            if (!(s.effectiveValueOrNull() instanceof Value.Ref r)) {
                return null;
            }
            if (f.links == null || f.links.length != slots.size()) {
                f.links = new Fact[slots.size()];
            }
            Fact to = f.links[j];
            if (to == null || to.gone()) {
                to = facts.get(r.frame());
                f.links[j] = to;
            }
            return to;
        }
        return null;
    }

    /** As {@link #value(String, String)}, with the instance's record (may be null) at hand. */
    Optional<Value> value(Fact f, String frame, String slot) {
        return Optional.ofNullable(valueOrNull(f, frame, slot));
    }

    /** {@link #value(Fact, String, String)}, or null where it is empty (see {@link #followOrNull}). */
    private Value valueOrNull(Fact f, String frame, String slot) {
        if (f != null && f.frame != null) {
            List<Slot> slots = f.frame.slots();
            for (int i = 0; i < slots.size(); i++) {
                Slot s = slots.get(i);
                if (s.name().equals(slot)) {
                    Value v = s.effectiveValueOrNull();
                    if (v != null) {
                        return v;
                    }
                    break;
                }
            }
        }
        return kb.contains(frame) ? kb.value(frame, slot).orElse(null) : null;
    }
}
