package org.kicnp.inference;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.kicnp.core.NameTable;

/**
 * Truth maintenance records: which derived instance rests on which instances, which bindings have fired
 * (refraction), which instances unshared slots have consumed, and which unique-slot keys are taken.
 * Owned by the engine thread.
 */
final class Supports {
    private final Map<String, String> claims = new HashMap<>();
    private final Map<String, String> keys = new HashMap<>();
    private final Map<String, List<String>> heldBy = new HashMap<>();
    private final Set<String> failed = new HashSet<>();
    /** Where each fact's fired bindings are kept, so that a fact leaving frees them. */
    private final FactView facts;

    Supports(FactView facts) {
        this.facts = facts;
    }

    Optional<Derivation> derivation(String instance) {
        FactView.Fact f = facts.get(instance);
        return Optional.ofNullable(f == null ? null : f.derivation);
    }

    /** The live instances a frame derived (a scan: frames change rarely, firings often). */
    Set<String> derivedFrom(String frame) {
        List<Derivation> found = new ArrayList<>();
        for (FactView.Fact f : facts.all()) {
            if (f.derivation != null && f.derivation.frame().equals(frame)) {
                found.add(f.derivation);
            }
        }
        found.sort(java.util.Comparator.comparingLong(Derivation::firing));
        Set<String> out = new LinkedHashSet<>();
        found.forEach(d -> out.add(d.instance()));
        return out;
    }

    /** The derived instances resting directly on a fact, in the order they were made (a copy). */
    List<String> dependentsOf(String fact) {
        FactView.Fact f = facts.get(fact);
        return f == null ? List.of() : List.copyOf(f.dependents());
    }

    /** Records a new derived instance and, for a firing, what its unshared and unique slots now hold. */
    void record(Derivation d, Optional<Rule> rule) {
        record(d, rule.orElse(null), new FactView.Fact[0], NameTable.numberOf(d.instance()));
    }

    /**
     * As {@link #record(Derivation, Optional)}, with the rule that fired (null: none, a script made the instance) and
     * the records of (some of) the supporting instances already at hand in {@code known}; the others are looked up.
     * A firing's instance has a name never used before (the engine's counter) and its binding holds each instance
     * once, so it is added to each support's dependents without looking for it there first. {@code number} is
     * {@link NameTable#numberOf} of the new instance's name (a firing knows it from its counter). Returns the new
     * instance's record.
     */
    FactView.Fact record(Derivation d, Rule rule, FactView.Fact[] known, int number) {
        FactView.Fact self = facts.touch(d.instance(), number);
        self.derivation = d;
        for (int i = 0, n = d.width(); i < n; i++) { // d.supports() without its list
            String support = d.factAt(i);
            // A firing's known records are its required slots' facts, in the binding's order: usually no search.
            FactView.Fact r = i < known.length && known[i].name == support ? known[i] : recordOf(support, known);
            if (rule != null) {
                r.newDependent(d.instance());
            } else {
                r.dependent(d.instance());
            }
        }
        // Plain tests rather than ifPresent with lambdas: each would capture d (and known), an object per firing.
        if (d.createdBy().isPresent()) {
            recordOf(d.createdBy().get(), known).dependent(d.instance());
        }
        if (rule != null && rule.claims()) {
            claim(rule, d);
        }
        return self;
    }

    /** Takes the claims and the key that the rule's unshared and unique slots give the derived instance. */
    private void claim(Rule r, Derivation d) {
        List<String> held = new ArrayList<>();
        for (SlotPattern p : r.patterns()) {
            String v = d.binding().get(p.slot());
            if (v != null && p.claims()) {
                String c = claimKey(r.frame(), p.slot(), v);
                claims.put(c, d.instance());
                held.add(c);
            }
        }
        uniqueKey(r, d.binding()).ifPresent(k -> {
            keys.put(k, d.instance());
            held.add(k);
        });
        heldBy.put(d.instance(), held);
    }

    /**
     * A behavior frame was recompiled (edited): its facets may have changed, so the claims and keys of the live
     * instances it fired are taken again under the new rule, oldest firing first. Returns, oldest first, the
     * instances that now claim what an older one holds, each with the reason; they keep no claims.
     */
    Map<String, String> reclaim(Rule r, Collection<String> fired) {
        for (String i : fired) {
            for (String c : heldBy.getOrDefault(i, List.of())) {
                claims.remove(c);
                keys.remove(c);
            }
            heldBy.remove(i);
        }
        Map<String, String> conflicts = new LinkedHashMap<>();
        for (String i : fired) {
            Derivation d = derivation(i).orElse(null);
            if (d == null || !r.claims()) {
                continue;
            }
            Optional<String> taken = taken(r, d.binding());
            if (taken.isPresent()) {
                conflicts.put(i, taken.get());
            } else {
                claim(r, d);
            }
        }
        return conflicts;
    }

    /**
     * A behavior frame was recompiled: the bindings of the live instances it fired stay refracted under the new
     * rule, whose refraction keys list the instances in its own slot order (an edit may have reordered the slots).
     */
    void refract(Rule r, Collection<String> fired) {
        for (String i : fired) {
            Derivation d = derivation(i).orElse(null);
            String[] bound = d == null ? null : Activation.factsOf(r, d.binding());
            if (bound == null || java.util.Arrays.asList(bound).contains(null)) {
                continue; // a required slot it does not fill: it no longer fits and is retracted
            }
            BindingKey key = new BindingKey(r.frame(), bound);
            for (String name : bound) {
                FactView.Fact f = facts.get(name);
                if (f != null) {
                    f.fired(key);
                }
            }
        }
    }

    /** What an earlier instance of the rule already holds of a binding's claims or key, in words, if anything. */
    private Optional<String> taken(Rule r, Map<String, String> binding) {
        for (SlotPattern p : r.patterns()) {
            String v = binding.get(p.slot());
            String holder = v == null || !p.claims() ? null : claims.get(claimKey(r.frame(), p.slot(), v));
            if (holder != null) {
                return Optional.of((p.shared() ? "unique" : "unshared") + " slot '" + p.slot() + "' already holds '"
                        + v + "' in '" + holder + "'");
            }
        }
        return uniqueKey(r, binding).filter(keys::containsKey)
                .map(k -> "unique slots " + r.uniqueSlots() + " already hold these values in '" + keys.get(k) + "'");
    }

    /** The record of a fact: one of {@code known} when it is there (a few, compared by name), else looked up. */
    private FactView.Fact recordOf(String name, FactView.Fact[] known) {
        for (FactView.Fact k : known) {
            if (k.name.equals(name)) {
                return k;
            }
        }
        return facts.touch(name);
    }

    /** Forgets a derived instance; returns its derivation. Its claims and keys are freed. */
    Optional<Derivation> release(String instance) {
        FactView.Fact self = facts.get(instance);
        Derivation d = self == null ? null : self.derivation;
        if (d == null) {
            return Optional.empty();
        }
        self.derivation = null;
        if (self.frame == null) {
            facts.remove(instance);
        }
        for (String s : d.supports()) {
            FactView.Fact f = facts.get(s);
            if (f != null) {
                f.dependents = Bag.remove(f.dependents, instance);
            }
        }
        for (String c : heldBy.getOrDefault(instance, List.of())) {
            claims.remove(c);
            keys.remove(c);
        }
        heldBy.remove(instance);
        return Optional.of(d);
    }

    void markFailed(String instance) {
        failed.add(instance);
    }

    boolean takeFailed(String instance) {
        return failed.remove(instance);
    }

    /** Every live derived instance resting, directly or not, on {@code root}; {@code root} not included. */
    Set<String> closure(String root) {
        Set<String> out = new LinkedHashSet<>();
        Deque<String> todo = new ArrayDeque<>(List.of(root));
        while (!todo.isEmpty()) {
            FactView.Fact f = facts.get(todo.pop());
            if (f == null) {
                continue;
            }
            for (String d : f.dependents()) {
                if (out.add(d)) {
                    todo.push(d);
                }
            }
        }
        out.remove(root);
        return out;
    }

    /** Why a binding may not fire now, if it may not: refracted, consumed by an unshared slot, or key taken. */
    Optional<String> blocked(Rule r, String[] facts, BindingKey key) {
        return blocked(r, facts, this.facts.get(key.fact(0)), key);
    }

    /** As {@link #blocked(Rule, String[], BindingKey)}, with the first bound instance's record (or null) at hand. */
    Optional<String> blocked(Rule r, String[] facts, FactView.Fact first, BindingKey key) {
        if (first != null && first.hasFired(key)) {
            return Optional.of("refraction: this binding has already fired");
        }
        if (!r.claims()) {
            return Optional.empty();
        }
        List<SlotPattern> required = r.required();
        for (int i = 0; i < required.size(); i++) {
            SlotPattern p = required.get(i);
            String v = facts[i];
            if (!p.shared() && claims.containsKey(claimKey(r.frame(), p.slot(), v))) {
                return Optional.of("unshared slot '" + p.slot() + "' already holds '" + v + "' in '"
                        + claims.get(claimKey(r.frame(), p.slot(), v)) + "'");
            }
        }
        return uniqueKey(r, Activation.bindingOf(r, facts)).filter(keys::containsKey)
                .map(k -> "unique slots " + r.uniqueSlots() + " already hold these values in '" + keys.get(k) + "'");
    }

    boolean consumed(String frame, String slot, String fact) {
        return claims.containsKey(claimKey(frame, slot, fact));
    }

    /**
     * Refracts a binding that is firing now, once per firing: it was not refracted (else it would not fire), so its
     * key is in none of its facts' lists yet (a binding holds each fact once), and is added without a search.
     */
    void markFired(BindingKey key, FactView.Fact[] bound) {
        for (FactView.Fact f : bound) {
            f.firedNow(key);
        }
    }

    void unmarkFired(BindingKey key) {
        for (int i = 0, n = key.width(); i < n; i++) {
            FactView.Fact f = facts.get(key.fact(i));
            if (f != null) {
                f.unfire(key);
            }
        }
    }

    /** A fact left: bindings with it can never recur, and a re-asserted fact of that name is a new fact. */
    void factGone(String fact) {
        FactView.Fact f = facts.get(fact);
        if (f != null && f.fired != null) {
            List<BindingKey> ks = Bag.toList(f.fired);
            f.fired = null;
            for (BindingKey k : ks) {
                for (String other : k.facts()) {
                    FactView.Fact o = other.equals(fact) ? null : facts.get(other);
                    if (o != null) {
                        o.unfire(k);
                    }
                }
            }
        }
    }

    static String claimKey(String frame, String slot, String fact) {
        return "c\u0000" + frame + '\u0000' + slot + '\u0000' + fact;
    }

    static Optional<String> uniqueKey(Rule r, Map<String, String> binding) {
        List<String> us = r.uniqueSlots();
        if (us.isEmpty()) {
            return Optional.empty();
        }
        StringBuilder sb = new StringBuilder("u\u0000").append(r.frame());
        for (String s : us) {
            sb.append('\u0000').append(binding.getOrDefault(s, ""));
        }
        return Optional.of(sb.toString());
    }
}
