package org.kicnp.inference;

import java.util.ArrayList;
import java.util.List;

/**
 * How the match network joins one rule, worked out once when the rule is installed, so that joining a new fact needs
 * no look-up by name: the memory of each required slot (by position in {@link Rule#required()}), for each starting
 * slot the others in the order they are bound, the required slots each condition refers to, and for each slot the
 * hash index that can answer its partners, with the path that computes the key from the slot already bound.
 *
 * <p>Partner look-ups come in two forms: the slot's own equality join ({@code mB: .key == mA.key}: with {@code mA}
 * bound, look up {@code mB}'s index on {@code key} with {@code mA.key}), or another slot's equality join that names
 * this slot ({@code mA} found from a bound {@code mB} through {@code mA}'s index on {@code key} with {@code mB.key}).
 * Either way the condition that the look-up answered holds for every partner found, when the index key compares
 * exactly ({@link Values#exactKey}), and is not tested again.
 */
final class JoinPlan {
    final Rule rule;
    /** Required slot names, by position. */
    final String[] slots;
    /** The memory of each required slot, by position. */
    final AlphaMemory[] memories;
    /** For each starting position, the other positions in binding order. */
    final int[][] order;
    /** For each position, the positions of the required slots its condition refers to. */
    final int[][] joins;
    /** For each position, the lookups that can find its partners (tried in order). */
    final Lookup[][] lookups;
    /**
     * The binding that joining a new fact builds, made once for the rule rather than once per fact: the match network
     * is owned by the engine thread, binds positions as it goes, and leaves every position unbound when it is done.
     */
    final JoinBinding binding;

    /**
     * A hash-index look-up for the partners of one slot: from the fact bound at {@code from}, follow {@code path}
     * to the key, then read index {@code index} of the slot's memory. {@code answers} is the position whose
     * condition (an equality join) the look-up decides.
     */
    record Lookup(int from, List<String> path, int index, int answers) {
    }

    private JoinPlan(Rule rule, AlphaMemory[] memories) {
        this.rule = rule;
        this.memories = memories;
        List<SlotPattern> req = rule.required();
        int n = req.size();
        slots = new String[n];
        for (int i = 0; i < n; i++) {
            slots[i] = req.get(i).slot();
        }
        order = new int[n][];
        joins = new int[n][];
        lookups = new Lookup[n][];
        binding = new JoinBinding(slots);
        for (int i = 0; i < n; i++) {
            int[] o = new int[n - 1];
            for (int j = 0, k = 0; j < n; j++) {
                if (j != i) {
                    o[k++] = j;
                }
            }
            order[i] = o;
            List<Integer> js = new ArrayList<>();
            for (String s : req.get(i).joins()) {
                int at = position(s);
                if (at >= 0) {
                    js.add(at);
                }
            }
            joins[i] = js.stream().mapToInt(Integer::intValue).sorted().toArray();
        }
        for (int i = 0; i < n; i++) {
            List<Lookup> ls = new ArrayList<>();
            SlotPattern p = req.get(i);
            if (p.equality().isPresent() && position(p.equality().get().head()) >= 0) {
                var eq = p.equality().get();
                ls.add(new Lookup(position(eq.head()), eq.rest(), memories[i].addIndex(eq.left()), i));
            }
            for (int q = 0; q < n; q++) {
                SlotPattern other = req.get(q);
                if (q != i && other.equality().isPresent() && other.equality().get().head().equals(p.slot())) {
                    var eq = other.equality().get();
                    ls.add(new Lookup(q, eq.left(), memories[i].addIndex(eq.rest()), q));
                }
            }
            lookups[i] = ls.toArray(Lookup[]::new);
        }
    }

    /**
     * The plan of a rule whose required slots have the given memories (by position); adds to those memories the
     * indexes its look-ups need.
     */
    static JoinPlan of(Rule rule, AlphaMemory[] memories) {
        return new JoinPlan(rule, memories);
    }

    int position(String slot) {
        for (int i = 0; i < slots.length; i++) {
            if (slots[i].equals(slot)) {
                return i;
            }
        }
        return -1;
    }
}
