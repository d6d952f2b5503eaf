package org.kicnp.inference;

import java.util.AbstractList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.RandomAccess;
import org.kicnp.core.Value;

/**
 * The condition part of an explanation: for each bound slot of a firing, its condition and the value it was tested
 * on (the candidate's value along the condition's left path, or the instance itself), taken when the frame fires so
 * that a later change does not rewrite history.
 *
 * <p>What a firing takes is the values themselves ({@link Value}s are immutable, and an instance's name is a
 * string); the {@link Derivation.CheckedCondition} records and the values' texts are made when the list is read. Every
 * firing takes its conditions, and few are ever explained: a record, a list and a text per slot and firing was most
 * of the cost.
 */
final class CheckedConditions extends AbstractList<Derivation.CheckedCondition> implements RandomAccess {
    private final List<SlotPattern> patterns;
    /** Which of {@link #patterns} were checked, by index; null: all of them, in order. */
    private final int[] which;
    /** The value each checked pattern was tested on: a {@link Value}, or an instance's name. */
    private final Object[] tested;

    /** The list of {@code tested[i]} as the value tested by {@code patterns.get(which == null ? i : which[i])}. */
    CheckedConditions(List<SlotPattern> patterns, int[] which, Object[] tested) {
        this.patterns = patterns;
        this.which = which;
        this.tested = tested;
    }

    /**
     * What a firing of {@code r}, a rule with no optional slots, keeps of the values it tests its conditions on: for
     * each of its patterns (its required slots, in order) whose condition reads a path, the value along that path from
     * the fact bound there ({@code refs}, in the same order), or the fact's name where the path leads nowhere. The
     * other patterns are tested on the fact's name, which the binding holds already, so nothing is kept for them: the
     * result is null (no pattern reads a path), the one value itself, or an array of them in pattern order. Every
     * derived instance keeps this for as long as it lives; {@link #expand} gives back what {@link #of} would list.
     */
    static Object kept(Rule r, FactView.Fact[] refs, FactView facts, Conditions conditions) {
        List<SlotPattern> patterns = r.required();
        int paths = pathsRead(patterns, refs.length);
        Object[] many = paths > 1 ? new Object[paths] : null;
        Object one = null;
        for (int i = 0, k = 0; i < refs.length; i++) {
            SlotPattern p = patterns.get(i);
            if (readsPath(p)) {
                Object v = testedOn(p, refs[i], refs[i].name, facts, conditions);
                if (many != null) {
                    many[k++] = v;
                } else {
                    one = v;
                }
            }
        }
        return many != null ? many : one;
    }

    /**
     * The value each of the first {@code facts.length} patterns was tested on, from what {@link #kept} kept and the
     * facts bound to them ({@code facts}, in the same order).
     */
    static Object[] expand(List<SlotPattern> patterns, String[] facts, Object kept) {
        int paths = pathsRead(patterns, facts.length);
        Object[] tested = new Object[facts.length];
        for (int i = 0, k = 0; i < facts.length; i++) {
            if (readsPath(patterns.get(i))) {
                tested[i] = paths == 1 ? kept : ((Object[]) kept)[k];
                k++;
            } else {
                tested[i] = facts[i];
            }
        }
        return tested;
    }

    private static boolean readsPath(SlotPattern p) {
        return p.condition().testedPath().isPresent();
    }

    private static int pathsRead(List<SlotPattern> patterns, int n) {
        int count = 0;
        for (int i = 0; i < n; i++) {
            if (readsPath(patterns.get(i))) {
                count++;
            }
        }
        return count;
    }

    /** The value pattern {@code p}'s condition is tested on: along its left path from the fact, or the fact's name. */
    private static Object testedOn(SlotPattern p, FactView.Fact record, String fact, FactView facts,
            Conditions conditions) {
        List<String> path = p.condition().testedPath().orElse(null);
        if (path == null) {
            return fact;
        }
        Value v = record != null ? facts.followOrNull(record, path, conditions)
                : conditions.follow(Value.ref(fact), path).orElse(null);
        return v != null ? v : fact;
    }

    /**
     * The checked conditions of a firing of {@code r} with {@code binding} (slot → instance); {@code refs} are the
     * records of the facts bound to the required slots, in the rule's order, so their values are read without a
     * look-up by name. An immutable list.
     */
    static List<Derivation.CheckedCondition> of(Rule r, Map<String, String> binding, FactView.Fact[] refs,
            FactView facts, Conditions conditions) {
        List<SlotPattern> patterns = r.patterns(); // the required slots in order, then the optional ones
        int n = patterns.size();
        Object[] tested = new Object[n];
        int[] which = null;
        int count = 0;
        for (int i = 0; i < n; i++) {
            SlotPattern p = patterns.get(i);
            FactView.Fact record = i < refs.length ? refs[i] : null; // refs follow the required slots' order
            String fact = record != null ? record.name : binding.get(p.slot());
            if (fact == null) {
                if (which == null) { // an optional slot left unbound: from here on, say which were checked
                    which = new int[n];
                    for (int j = 0; j < count; j++) {
                        which[j] = j;
                    }
                }
                continue;
            }
            Object value = testedOn(p, record, fact, facts, conditions);
            if (which != null) {
                which[count] = i;
            }
            tested[count++] = value;
        }
        return which == null ? new CheckedConditions(patterns, null, tested)
                : new CheckedConditions(patterns, Arrays.copyOf(which, count), Arrays.copyOf(tested, count));
    }

    @Override public Derivation.CheckedCondition get(int index) {
        Object value = tested[index]; // throws for an index out of range, as a list does
        SlotPattern p = patterns.get(which == null ? index : which[index]);
        return new Derivation.CheckedCondition(p.slot(), p.conditionText(),
                value instanceof Value v ? v.text() : (String) value);
    }

    @Override public int size() {
        return tested.length;
    }
}
