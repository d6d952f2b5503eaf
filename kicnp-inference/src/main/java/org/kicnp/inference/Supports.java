package org.kicnp.inference;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * Truth maintenance records: which derived instance rests on which instances, which bindings have fired
 * (refraction), which instances unshared slots have consumed, and which unique-slot keys are taken.
 * Owned by the engine thread.
 */
final class Supports {
    private final Map<String, Derivation> derivations = new HashMap<>();
    private final Map<String, Set<String>> dependents = new HashMap<>();
    private final Map<String, Set<String>> byFrame = new HashMap<>();
    private final Set<String> fired = new HashSet<>();
    private final Map<String, Set<String>> firedByFact = new HashMap<>();
    private final Map<String, String> claims = new HashMap<>();
    private final Map<String, String> keys = new HashMap<>();
    private final Map<String, List<String>> heldBy = new HashMap<>();
    private final Set<String> failed = new HashSet<>();

    Optional<Derivation> derivation(String instance) {
        return Optional.ofNullable(derivations.get(instance));
    }

    boolean isDerived(String instance) {
        return derivations.containsKey(instance);
    }

    Set<String> derivedFrom(String frame) {
        return Set.copyOf(byFrame.getOrDefault(frame, Set.of()));
    }

    Set<String> dependentsOf(String fact) {
        return Set.copyOf(dependents.getOrDefault(fact, Set.of()));
    }

    /** Records a new derived instance and, for a firing, what its unshared and unique slots now hold. */
    void record(Derivation d, Optional<Rule> rule) {
        derivations.put(d.instance(), d);
        byFrame.computeIfAbsent(d.frame(), k -> new LinkedHashSet<>()).add(d.instance());
        for (String s : d.supports()) {
            dependents.computeIfAbsent(s, k -> new LinkedHashSet<>()).add(d.instance());
        }
        rule.ifPresent(r -> {
            List<String> held = new ArrayList<>();
            for (SlotPattern p : r.patterns()) {
                String v = d.binding().get(p.slot());
                if (v != null && !p.shared()) {
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
        });
    }

    /** Forgets a derived instance; returns its derivation. Its claims and keys are freed. */
    Optional<Derivation> release(String instance) {
        Derivation d = derivations.remove(instance);
        if (d == null) {
            return Optional.empty();
        }
        Set<String> f = byFrame.get(d.frame());
        if (f != null) {
            f.remove(instance);
        }
        for (String s : d.supports()) {
            Set<String> deps = dependents.get(s);
            if (deps != null) {
                deps.remove(instance);
                if (deps.isEmpty()) {
                    dependents.remove(s);
                }
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
            for (String d : dependents.getOrDefault(todo.pop(), Set.of())) {
                if (out.add(d)) {
                    todo.push(d);
                }
            }
        }
        out.remove(root);
        return out;
    }

    /** Why a binding may not fire now, if it may not: refracted, consumed by an unshared slot, or key taken. */
    Optional<String> blocked(Rule r, Map<String, String> binding, String key) {
        if (fired.contains(key)) {
            return Optional.of("refraction: this binding has already fired");
        }
        for (SlotPattern p : r.required()) {
            String v = binding.get(p.slot());
            if (!p.shared() && claims.containsKey(claimKey(r.frame(), p.slot(), v))) {
                return Optional.of("unshared slot '" + p.slot() + "' already holds '" + v + "' in '"
                        + claims.get(claimKey(r.frame(), p.slot(), v)) + "'");
            }
        }
        return uniqueKey(r, binding).filter(keys::containsKey)
                .map(k -> "unique slots " + r.uniqueSlots() + " already hold these values in '" + keys.get(k) + "'");
    }

    boolean consumed(String frame, String slot, String fact) {
        return claims.containsKey(claimKey(frame, slot, fact));
    }

    void markFired(String key, Iterable<String> facts) {
        fired.add(key);
        for (String f : facts) {
            firedByFact.computeIfAbsent(f, k -> new HashSet<>()).add(key);
        }
    }

    void unmarkFired(String key) {
        fired.remove(key);
    }

    /** A fact left: bindings with it can never recur, and a re-asserted fact of that name is a new fact. */
    void factGone(String fact) {
        Set<String> ks = firedByFact.remove(fact);
        if (ks != null) {
            fired.removeAll(ks);
        }
    }

    private static String claimKey(String frame, String slot, String fact) {
        return "c\u0000" + frame + '\u0000' + slot + '\u0000' + fact;
    }

    private static Optional<String> uniqueKey(Rule r, Map<String, String> binding) {
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
