package org.kicnp.inference;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashMap;
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
    /** Where each fact's memories are listed (its {@link FactView.Fact}). */
    private final FactView facts;
    /** Per class, the memories an instance of it enters (its own and its ancestors'); dropped on any class change. */
    private final Map<String, List<AlphaMemory>> entryCache = new HashMap<>();
    /** Per rule, per required pattern (by position): the other required patterns, and the required slots it joins. */
    private final Map<Rule, Plan> plans = new HashMap<>();

    MatchNetwork(KnowledgeBase kb, Conditions conditions) {
        this(kb, conditions, new FactView(kb));
    }

    MatchNetwork(KnowledgeBase kb, Conditions conditions, FactView facts) {
        this.kb = kb;
        this.conditions = conditions;
        this.facts = facts;
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
        plans.put(rule, Plan.of(rule));
        entryCache.clear();
        for (AlphaMemory m : mems.values()) {
            byClass.computeIfAbsent(m.pattern().argument(), k -> new ArrayList<>()).add(m);
            for (var f : kb.instancesOf(m.pattern().argument())) {
                offer(m, f.name());
            }
        }
        List<Match> out = new ArrayList<>();
        SlotPattern first = rule.required().getFirst();
        for (String fact : List.copyOf(mems.get(first.slot()).facts())) {
            complete(rule, first, fact, out);
        }
        return out;
    }

    void removeRule(String frame) {
        Map<String, AlphaMemory> mems = memoriesByRule.remove(frame);
        if (mems == null) {
            return;
        }
        entryCache.clear();
        plans.keySet().removeIf(r -> r.frame().equals(frame));
        for (AlphaMemory m : mems.values()) {
            byClass.getOrDefault(m.pattern().argument(), new ArrayList<>()).remove(m);
            for (String f : m.facts()) {
                FactView.Fact fact = facts.get(f);
                if (fact != null) {
                    fact.leave(m);
                }
            }
        }
    }

    boolean hasRule(String frame) {
        return memoriesByRule.containsKey(frame);
    }

    /** Enters an instance of {@code className} into every memory it fits; returns the bindings it completes. */
    List<Match> insert(String fact, String className) {
        List<AlphaMemory> candidates = entryCache.get(className);
        if (candidates == null) {
            candidates = new ArrayList<>();
            List<String> classes = new ArrayList<>();
            classes.add(className);
            classes.addAll(kb.ancestors(className));
            for (String c : classes) {
                candidates.addAll(byClass.getOrDefault(c, List.of()));
            }
            entryCache.put(className, candidates);
        }
        if (candidates.isEmpty()) {
            return List.of();
        }
        List<AlphaMemory> entered = new ArrayList<>(candidates.size());
        for (AlphaMemory m : candidates) {
            if (offer(m, fact)) {
                entered.add(m);
            }
        }
        List<Match> out = new ArrayList<>();
        for (AlphaMemory m : entered) {
            if (m.pattern().required()) {
                complete(m.rule(), m.pattern(), fact, out);
            }
        }
        return out;
    }

    /** Forgets what it derived from the class hierarchy: call when a class frame was added, changed or removed. */
    void classesChanged() {
        entryCache.clear();
    }

    /** Matches again one fact in one slot of one rule: after a claim or key on it was freed. */
    List<Match> rematch(String rule, String slot, String fact) {
        Map<String, AlphaMemory> mems = memoriesByRule.get(rule);
        if (mems == null || !mems.containsKey(slot) || !mems.get(slot).contains(fact)
                || !mems.get(slot).pattern().required()) {
            return List.of();
        }
        List<Match> out = new ArrayList<>();
        complete(mems.get(slot).rule(), mems.get(slot).pattern(), fact, out);
        return out;
    }

    /** A complete binding of a rule's required slots: the instances in the order of {@link Rule#required()}. */
    record Match(Rule rule, String[] facts) {
        /** The binding as slot → instance, in slot order (a new map). */
        Map<String, String> binding() {
            return Activation.bindingOf(rule, facts);
        }
    }

    /** Takes a fact out of every memory it is in. */
    void retract(String fact) {
        FactView.Fact f = facts.get(fact);
        if (f != null) {
            f.leaveAll();
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
        Value[] keys = m.add(fact, (f, path) -> conditions.follow(Value.ref(f), path));
        facts.touch(fact).enter(m, keys);
        return true;
    }

    /** Every complete binding of the rule's required slots with {@code fact} in {@code start}. */
    private void complete(Rule rule, SlotPattern start, String fact, List<Match> out) {
        Plan plan = plan(rule);
        Map<String, String> b = new SlotBinding(rule.required().size());
        b.put(start.slot(), fact);
        if (!joinsHold(rule, plan, start, b)) {
            return;
        }
        extend(rule, plan, b, plan.others(start), 0, out);
    }

    private Plan plan(Rule rule) {
        Plan p = plans.get(rule);
        if (p == null) {
            p = Plan.of(rule);
            plans.put(rule, p);
        }
        return p;
    }

    private void extend(Rule rule, Plan plan, Map<String, String> b, List<SlotPattern> todo, int k, List<Match> out) {
        if (k == todo.size()) {
            List<SlotPattern> req = rule.required();
            String[] facts = new String[req.size()];
            for (int i = 0; i < facts.length; i++) {
                facts[i] = b.get(req.get(i).slot());
            }
            out.add(new Match(rule, facts));
            return;
        }
        SlotPattern p = todo.get(k);
        for (String c : partners(rule, p, b)) {
            if (b.containsValue(c)) {
                continue;
            }
            b.put(p.slot(), c);
            if (joinsHold(rule, plan, p, b)) {
                extend(rule, plan, b, todo, k + 1, out);
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
        return joinsHold(rule, plan(rule), p, b);
    }

    private boolean joinsHold(Rule rule, Plan plan, SlotPattern p, Map<String, String> b) {
        List<SlotPattern> required = rule.required();
        for (int i = 0; i < required.size(); i++) {
            SlotPattern q = required.get(i);
            if (q.joins().isEmpty() || !b.containsKey(q.slot()) || (q != p && !q.joins().contains(p.slot()))) {
                continue;
            }
            if (!allBound(plan.requiredJoins(i), b)) {
                continue;
            }
            if (!conditions.holds(q.condition(), Value.ref(b.get(q.slot())), rule.frame(), b)) {
                return false;
            }
        }
        return true;
    }

    private static boolean allBound(List<String> slots, Map<String, String> b) {
        for (int i = 0; i < slots.size(); i++) {
            if (!b.containsKey(slots.get(i))) {
                return false;
            }
        }
        return true;
    }

    /**
     * What joining a rule needs, worked out once per rule: for each required pattern (by position), the other
     * required patterns in order, and the slots among its joins that are required (the ones a binding must hold
     * before its condition can be tested).
     */
    private record Plan(Map<SlotPattern, List<SlotPattern>> others, List<List<String>> requiredJoins) {
        static Plan of(Rule rule) {
            Map<SlotPattern, List<SlotPattern>> others = new java.util.IdentityHashMap<>();
            List<List<String>> joins = new ArrayList<>();
            Set<String> requiredSlots = new java.util.HashSet<>();
            rule.required().forEach(p -> requiredSlots.add(p.slot()));
            for (SlotPattern p : rule.required()) {
                others.put(p, rule.required().stream().filter(q -> q != p).toList());
                joins.add(p.joins().stream().filter(requiredSlots::contains).toList());
            }
            return new Plan(others, joins);
        }

        List<SlotPattern> others(SlotPattern start) {
            return others.get(start);
        }

        List<String> requiredJoins(int index) {
            return requiredJoins.get(index);
        }
    }
}
