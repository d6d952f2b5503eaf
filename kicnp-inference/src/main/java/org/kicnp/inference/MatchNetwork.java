package org.kicnp.inference;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;

/**
 * The forward-chaining match network, in the TREAT family: one alpha memory per (behavior frame, instance slot),
 * reached from the class of a changed instance through its ancestors, and complete bindings found by joining a new
 * fact against the other memories, through hash indexes wherever the slots are joined by equality. A change costs
 * the memories it enters and the bindings it completes, never a scan of every instance. Owned by the engine thread.
 */
final class MatchNetwork {
    private final KnowledgeBase kb;
    private final Conditions conditions;
    private final Map<String, Map<String, AlphaMemory>> memoriesByRule = new HashMap<>();
    private final Map<String, List<AlphaMemory>> byClass = new HashMap<>();
    private final Map<String, Set<AlphaMemory>> memberships = new HashMap<>();

    MatchNetwork(KnowledgeBase kb, Conditions conditions) {
        this.kb = kb;
        this.conditions = conditions;
    }

    /** Installs a rule and fills its memories from the instances there are now; returns every complete binding. */
    List<Match> addRule(Rule rule) {
        Map<String, AlphaMemory> mems = new LinkedHashMap<>();
        for (SlotPattern p : rule.patterns()) {
            mems.put(p.slot(), new AlphaMemory(rule, p));
        }
        for (SlotPattern p : rule.patterns()) {
            p.equality().ifPresent(eq -> {
                mems.get(p.slot()).addIndex(eq.left());
                mems.get(eq.head()).addIndex(eq.rest());
            });
        }
        memoriesByRule.put(rule.frame(), mems);
        for (AlphaMemory m : mems.values()) {
            byClass.computeIfAbsent(m.pattern().argument(), k -> new ArrayList<>()).add(m);
            for (var f : kb.instancesOf(m.pattern().argument())) {
                offer(m, f.name());
            }
        }
        List<Match> out = new ArrayList<>();
        SlotPattern first = rule.required().getFirst();
        for (String fact : List.copyOf(mems.get(first.slot()).facts())) {
            out.addAll(complete(rule, first, fact));
        }
        return out;
    }

    void removeRule(String frame) {
        Map<String, AlphaMemory> mems = memoriesByRule.remove(frame);
        if (mems == null) {
            return;
        }
        for (AlphaMemory m : mems.values()) {
            byClass.getOrDefault(m.pattern().argument(), new ArrayList<>()).remove(m);
            for (String f : m.facts()) {
                Set<AlphaMemory> s = memberships.get(f);
                if (s != null) {
                    s.remove(m);
                }
            }
        }
    }

    boolean hasRule(String frame) {
        return memoriesByRule.containsKey(frame);
    }

    /** Enters an instance of {@code className} into every memory it fits; returns the bindings it completes. */
    List<Match> insert(String fact, String className) {
        List<AlphaMemory> entered = new ArrayList<>();
        List<String> classes = new ArrayList<>();
        classes.add(className);
        classes.addAll(kb.ancestors(className));
        for (String c : classes) {
            for (AlphaMemory m : byClass.getOrDefault(c, List.of())) {
                if (offer(m, fact)) {
                    entered.add(m);
                }
            }
        }
        List<Match> out = new ArrayList<>();
        for (AlphaMemory m : entered) {
            if (m.pattern().required()) {
                out.addAll(complete(m.rule(), m.pattern(), fact));
            }
        }
        return out;
    }

    /** Matches again one fact in one slot of one rule: after a claim or key on it was freed. */
    List<Match> rematch(String rule, String slot, String fact) {
        Map<String, AlphaMemory> mems = memoriesByRule.get(rule);
        if (mems == null || !mems.containsKey(slot) || !mems.get(slot).contains(fact)
                || !mems.get(slot).pattern().required()) {
            return List.of();
        }
        return complete(mems.get(slot).rule(), mems.get(slot).pattern(), fact);
    }

    /** A complete binding of a rule's required slots. */
    record Match(Rule rule, Map<String, String> binding) { }

    /** Takes a fact out of every memory it is in. */
    void retract(String fact) {
        Set<AlphaMemory> in = memberships.remove(fact);
        if (in != null) {
            in.forEach(m -> m.remove(fact));
        }
    }

    /** The instances that could fill a slot of a rule now (right class, constant conditions hold). */
    Collection<String> candidates(String rule, String slot) {
        Map<String, AlphaMemory> mems = memoriesByRule.get(rule);
        return mems == null || !mems.containsKey(slot) ? List.of() : mems.get(slot).facts();
    }

    int memorySize(String rule, String slot) {
        return candidates(rule, slot).size();
    }

    private boolean offer(AlphaMemory m, String fact) {
        SlotPattern p = m.pattern();
        if (p.alpha() && !conditions.holds(p.condition(), Value.ref(fact), m.rule().frame(), Map.of())) {
            return false;
        }
        m.add(fact, (f, path) -> conditions.follow(Value.ref(f), path));
        memberships.computeIfAbsent(fact, k -> new LinkedHashSet<>()).add(m);
        return true;
    }

    /** Every complete binding of the rule's required slots with {@code fact} in {@code start}. */
    private List<Match> complete(Rule rule, SlotPattern start, String fact) {
        List<Match> out = new ArrayList<>();
        Map<String, String> b = new LinkedHashMap<>();
        b.put(start.slot(), fact);
        if (!joinsHold(rule, start, b)) {
            return out;
        }
        List<SlotPattern> todo = rule.required().stream().filter(p -> p != start).toList();
        extend(rule, b, todo, 0, out);
        return out;
    }

    private void extend(Rule rule, Map<String, String> b, List<SlotPattern> todo, int k, List<Match> out) {
        if (k == todo.size()) {
            Map<String, String> ordered = new LinkedHashMap<>();
            rule.required().forEach(p -> ordered.put(p.slot(), b.get(p.slot())));
            out.add(new Match(rule, ordered));
            return;
        }
        SlotPattern p = todo.get(k);
        for (String c : List.copyOf(partners(rule, p, b))) {
            if (b.containsValue(c)) {
                continue;
            }
            b.put(p.slot(), c);
            if (joinsHold(rule, p, b)) {
                extend(rule, b, todo, k + 1, out);
            }
            b.remove(p.slot());
        }
    }

    /** The partners for slot {@code p}: an index look-up when an equality join ties it to a bound slot. */
    private Collection<String> partners(Rule rule, SlotPattern p, Map<String, String> b) {
        Map<String, AlphaMemory> mems = memoriesByRule.get(rule.frame());
        AlphaMemory mem = mems.get(p.slot());
        if (p.equality().isPresent() && b.containsKey(p.equality().get().head())) {
            var eq = p.equality().get();
            Optional<Value> key = conditions.follow(Value.ref(b.get(eq.head())), eq.rest());
            return key.isEmpty() ? List.of() : mem.lookup(eq.left(), key.get());
        }
        for (SlotPattern q : rule.required()) {
            if (q.equality().isPresent() && q.equality().get().head().equals(p.slot()) && b.containsKey(q.slot())) {
                var eq = q.equality().get();
                Optional<Value> key = conditions.follow(Value.ref(b.get(q.slot())), eq.left());
                return key.isEmpty() ? List.of() : mem.lookup(eq.rest(), key.get());
            }
        }
        return mem.facts();
    }

    /** Join conditions that the assignment of {@code p} made decidable. */
    boolean joinsHold(Rule rule, SlotPattern p, Map<String, String> b) {
        for (SlotPattern q : rule.required()) {
            if (q.joins().isEmpty() || !b.containsKey(q.slot()) || (q != p && !q.joins().contains(p.slot()))) {
                continue;
            }
            if (!b.keySet().containsAll(q.joins().stream().filter(j -> rule.required().stream()
                    .anyMatch(r -> r.slot().equals(j))).toList())) {
                continue;
            }
            if (!conditions.holds(q.condition(), Value.ref(b.get(q.slot())), rule.frame(), b)) {
                return false;
            }
        }
        return true;
    }
}
