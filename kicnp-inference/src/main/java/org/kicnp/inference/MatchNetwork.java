package org.kicnp.inference;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiFunction;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;

/**
 * The forward-chaining match network, in the TREAT family: one alpha memory per (behavior frame, instance slot),
 * reached from the class of a changed instance through its ancestors, and complete bindings found by joining a new
 * fact against the other memories, through hash indexes wherever the slots are joined by equality. A change costs
 * the memories it enters and the bindings it completes, never a scan of every instance. Owned by the engine thread.
 */
final class MatchNetwork {
    /** The answer of a change that completes no binding (most do not): shared, so such a change makes no list. */
    private static final List<Match> NO_MATCHES = List.of();
    private final KnowledgeBase kb;
    private final Conditions conditions;
    private final Map<String, Map<String, AlphaMemory>> memoriesByRule = new HashMap<>();
    private final Map<String, List<AlphaMemory>> byClass = new HashMap<>();
    /** The engine's records of the facts; each holds its memberships of the memories. */
    private final FactView facts;
    /** Per class, the memories an instance of it enters (its own and its ancestors'); dropped on any class change. */
    private final Map<String, List<AlphaMemory>> entryCache = new HashMap<>();
    /**
     * The last {@value #RECENT} classes looked up in {@link #entryCache} and their memories, compared by identity: a
     * run's facts name their class with a few String objects over and over (the behavior frame's name in everything
     * a rule derives, one constant per kind of stimulus), and comparing references is cheaper than the map's hashing
     * for every fact. A class named by another String object of the same text is found in the map as before.
     * Dropped with the map.
     */
    private static final int RECENT = 8;
    private final String[] recentClasses = new String[RECENT];
    @SuppressWarnings("unchecked")
    private final List<AlphaMemory>[] recentEntering = new List[RECENT];
    private int nextRecent;
    /** Reads the value an index path reaches from a fact (null: none). */
    private final BiFunction<FactView.Fact, List<String>, Value> pathValue;

    MatchNetwork(KnowledgeBase kb, Conditions conditions) {
        this(kb, conditions, new FactView(kb));
    }

    MatchNetwork(KnowledgeBase kb, Conditions conditions, FactView facts) {
        this.kb = kb;
        this.conditions = conditions;
        this.facts = facts;
        this.pathValue = this::follow;
    }

    /** Installs a rule and fills its memories from the instances there are now; returns every complete binding. */
    List<Match> addRule(Rule rule) {
        Map<String, AlphaMemory> mems = new LinkedHashMap<>();
        for (SlotPattern p : rule.patterns()) {
            mems.put(p.slot(), new AlphaMemory(rule, p));
        }
        List<SlotPattern> required = rule.required();
        AlphaMemory[] byPosition = new AlphaMemory[required.size()];
        for (int i = 0; i < byPosition.length; i++) {
            byPosition[i] = mems.get(required.get(i).slot());
            byPosition[i].position = i;
        }
        JoinPlan plan = JoinPlan.of(rule, byPosition);
        mems.values().forEach(m -> m.plan = plan);
        memoriesByRule.put(rule.frame(), mems);
        clearEntering();
        for (AlphaMemory m : mems.values()) {
            byClass.computeIfAbsent(m.pattern().argument(), k -> new ArrayList<>()).add(m);
            for (var f : kb.instancesOf(m.pattern().argument())) {
                offer(m, facts.touch(f.name()));
            }
        }
        List<Match> out = NO_MATCHES;
        for (FactView.Fact fact : List.copyOf(byPosition[0].facts())) {
            out = complete(byPosition[0], fact, out);
        }
        return out;
    }

    void removeRule(String frame) {
        Map<String, AlphaMemory> mems = memoriesByRule.remove(frame);
        if (mems == null) {
            return;
        }
        clearEntering();
        for (AlphaMemory m : mems.values()) {
            byClass.getOrDefault(m.pattern().argument(), new ArrayList<>()).remove(m);
            for (FactView.Fact fact : m.facts()) {
                fact.leave(m);
            }
        }
    }

    boolean hasRule(String frame) {
        return memoriesByRule.containsKey(frame);
    }

    /** Enters an instance of {@code className} into every memory it fits; returns the bindings it completes. */
    List<Match> insert(String fact, String className) {
        return insert(facts.touch(fact), className);
    }

    /** The memories an instance of the class may enter: those of its class and its ancestors (cached). */
    private List<AlphaMemory> entering(String className) {
        for (int i = 0; i < RECENT; i++) {
            if (recentClasses[i] == className) {
                return recentEntering[i];
            }
        }
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
        recentClasses[nextRecent] = className;
        recentEntering[nextRecent] = candidates;
        nextRecent = (nextRecent + 1) % RECENT;
        return candidates;
    }

    /** Drops what {@link #entering} worked out from the rules and the class hierarchy. */
    private void clearEntering() {
        entryCache.clear();
        Arrays.fill(recentClasses, null);
        Arrays.fill(recentEntering, null);
    }

    /**
     * As {@link #insert(String, String)}, with the fact's record at hand. Each memory the fact enters is joined from
     * at once: a binding puts a fact in one slot only ({@link JoinBinding#holds}), so what the fact completes from one
     * memory does not depend on its being in the others yet, and the bindings come in the same order as when it
     * entered them all first. Most facts complete nothing (a stimulus waits for its partners): their answer is the
     * {@link #NO_MATCHES}, with no list made.
     */
    List<Match> insert(FactView.Fact fact, String className) {
        return insert(fact, className, NO_MATCHES);
    }

    /**
     * As {@link #insert(FactView.Fact, String)}, adding the bindings to {@code out} (a list the caller empties and
     * fills again for each fact, so that a fact that completes something makes no list): returns {@code out}, or a
     * new list when {@code out} is {@link #NO_MATCHES} and a binding was found.
     */
    List<Match> insert(FactView.Fact fact, String className, List<Match> out) {
        for (AlphaMemory m : entering(className)) {
            if (offer(m, fact) && m.position >= 0) {
                out = complete(m, fact, out);
            }
        }
        return out;
    }

    /** Makes room in the memories an instance of the class enters for {@code count} new ones ({@link AlphaMemory#expect}). */
    void expect(String className, int count) {
        for (AlphaMemory m : entering(className)) {
            m.expect(count);
        }
    }

    /** Forgets what it derived from the class hierarchy: call when a class frame was added, changed or removed. */
    void classesChanged() {
        clearEntering();
    }

    /** Matches again one fact in one slot of one rule: after a claim or key on it was freed. */
    List<Match> rematch(String rule, String slot, String fact) {
        Map<String, AlphaMemory> mems = memoriesByRule.get(rule);
        AlphaMemory m = mems == null ? null : mems.get(slot);
        FactView.Fact f = facts.get(fact);
        if (m == null || m.position < 0 || f == null || !m.contains(f)) {
            return List.of();
        }
        return complete(m, f, NO_MATCHES);
    }

    /** A complete binding of a rule's required slots: the instances' records in the order of {@link Rule#required()}. */
    record Match(Rule rule, FactView.Fact[] refs) {
        /** The instances' names, in slot order (a new array). */
        String[] facts() {
            String[] out = new String[refs.length];
            for (int i = 0; i < refs.length; i++) {
                out[i] = refs[i].name;
            }
            return out;
        }

        /** The binding as slot → instance, in slot order (a new map). */
        Map<String, String> binding() {
            return Activation.bindingOf(rule, facts());
        }
    }

    /**
     * Brings an instance's memberships up to date after a change that is not matched again (a non-reactive slot):
     * it leaves the memories whose constant conditions no longer hold for it, enters those where they now hold, and
     * is filed under the index keys its paths reach now. No binding is made: facts that come later meet it as it is.
     */
    void refresh(String fact, String className) {
        FactView.Fact f = facts.get(fact);
        if (f == null) {
            return;
        }
        for (AlphaMemory m : entering(className)) {
            SlotPattern p = m.pattern();
            boolean fits = !p.alpha() || conditions.holds(p.condition(), f.ref(), m.rule().frame(), Map.of());
            AlphaMemory.Entry e = f.entryIn(m);
            if (e != null && !fits) {
                m.remove(e);
                f.leave(m);
            } else if (e != null) {
                m.rekey(e, pathValue);
            } else if (fits) {
                offer(m, f);
            }
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
    List<String> candidates(String rule, String slot) {
        Map<String, AlphaMemory> mems = memoriesByRule.get(rule);
        if (mems == null || !mems.containsKey(slot)) {
            return List.of();
        }
        List<String> out = new ArrayList<>(mems.get(slot).size());
        mems.get(slot).facts().forEach(f -> out.add(f.name));
        return out;
    }

    int memorySize(String rule, String slot) {
        Map<String, AlphaMemory> mems = memoriesByRule.get(rule);
        return mems == null || !mems.containsKey(slot) ? 0 : mems.get(slot).size();
    }

    /** The value {@code path} reaches from a fact, or null (see {@link FactView#followOrNull}). */
    private Value follow(FactView.Fact fact, List<String> path) {
        return facts.followOrNull(fact, path, conditions);
    }

    /** Enters the fact into the memory when its constant conditions hold; false when not, or when it is in already. */
    private boolean offer(AlphaMemory m, FactView.Fact fact) {
        SlotPattern p = m.pattern();
        if (p.alpha() && !conditions.holds(p.condition(), fact.ref(), m.rule().frame(), Map.of())) {
            return false;
        }
        AlphaMemory.Entry e = m.add(fact, pathValue);
        if (e == null) {
            return false;
        }
        fact.enter(e);
        return true;
    }

    /**
     * Adds to {@code out} every complete binding of the rule's required slots with {@code fact} in the slot of memory
     * {@code start}; returns the list holding them: {@code out}, or a new list when {@code out} was {@link #NO_MATCHES}
     * and a binding was found.
     */
    private List<Match> complete(AlphaMemory start, FactView.Fact fact, List<Match> out) {
        JoinPlan plan = start.plan;
        JoinBinding b = plan.binding; // joining reads facts and conditions only: it never joins again inside
        int at = start.position;
        b.refs[at] = fact;
        try {
            return joinsHold(plan, at, -1, b) ? extend(plan, b, plan.order[at], 0, out) : out;
        } finally {
            Arrays.fill(b.refs, null); // also after a condition that threw: the next join starts unbound
        }
    }

    /** Extends a partial binding over the positions {@code todo} from its {@code k}th; answers as {@link #complete}. */
    private List<Match> extend(JoinPlan plan, JoinBinding b, int[] todo, int k, List<Match> out) {
        if (k == todo.length) {
            if (out == NO_MATCHES) {
                out = new ArrayList<>(2);
            }
            out.add(new Match(plan.rule, b.refs.clone()));
            return out;
        }
        int at = todo[k];
        AlphaMemory mem = plan.memories[at];
        for (JoinPlan.Lookup l : plan.lookups[at]) {
            FactView.Fact from = b.refs[l.from()];
            if (from == null) {
                continue;
            }
            Value key = follow(from, l.path());
            if (key == null) {
                return out;
            }
            Value k0 = Values.key(key);
            Object bucket = mem.bucket(l.index(), k0);
            int decided = Values.exactKey(k0) ? l.answers() : -1;
            if (bucket instanceof FactView.Fact one) { // a key most often files one fact: the bucket is that fact
                out = tryPartner(plan, b, todo, k, at, decided, one, out);
            } else if (bucket instanceof Object[] few) { // else a short array, read without an iterator
                for (Object c : few) {
                    if (c == null) {
                        break;
                    }
                    out = tryPartner(plan, b, todo, k, at, decided, (FactView.Fact) c, out);
                }
            } else if (bucket != null) {
                for (FactView.Fact c : Bag.<FactView.Fact>toList(bucket)) {
                    out = tryPartner(plan, b, todo, k, at, decided, c, out);
                }
            }
            b.refs[at] = null;
            return out;
        }
        for (FactView.Fact c : mem.facts()) {
            out = tryPartner(plan, b, todo, k, at, -1, c, out);
        }
        b.refs[at] = null;
        return out;
    }

    /** Binds {@code c} at position {@code at} and extends from there when the joins it decides hold. */
    private List<Match> tryPartner(JoinPlan plan, JoinBinding b, int[] todo, int k, int at, int decided,
            FactView.Fact c, List<Match> out) {
        if (b.holds(c)) {
            return out;
        }
        b.refs[at] = c;
        return joinsHold(plan, at, decided, b) ? extend(plan, b, todo, k + 1, out) : out;
    }

    /**
     * Whether the join conditions that binding position {@code at} made decidable hold: the condition of each bound
     * slot that refers to {@code at} (or is {@code at}'s own), once every slot it refers to is bound.
     * {@code decided}: a position whose condition the index look-up has answered already (-1: none).
     */
    private boolean joinsHold(JoinPlan plan, int at, int decided, JoinBinding b) {
        List<SlotPattern> required = plan.rule.required();
        for (int i = 0; i < required.size(); i++) {
            int[] js = plan.joins[i];
            if (js.length == 0 || i == decided || b.refs[i] == null || (i != at && !contains(js, at))
                    || !allBound(js, b)) {
                continue;
            }
            if (!conditions.holds(required.get(i).condition(), b.refs[i].ref(), plan.rule.frame(), b)) {
                return false;
            }
        }
        return true;
    }

    private static boolean contains(int[] xs, int x) {
        for (int v : xs) {
            if (v == x) {
                return true;
            }
        }
        return false;
    }

    private static boolean allBound(int[] positions, JoinBinding b) {
        for (int p : positions) {
            if (b.refs[p] == null) {
                return false;
            }
        }
        return true;
    }
}
