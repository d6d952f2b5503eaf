package org.kicnp.inference;

import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;

/**
 * The conflict set, in conflict-resolution order: explicit priority (higher first), then specificity (the deeper
 * frame in the hierarchy first, then the frame with more conditions), then recency (the binding whose newest fact
 * is newest first), then the order activations were made. Activations are withdrawn when a fact they bind leaves.
 */
final class Agenda {
    static final Comparator<Activation> ORDER = Comparator
            .comparingInt((Activation a) -> -a.rule().priority())
            .thenComparingInt(a -> -a.rule().depth())
            .thenComparingInt(a -> -a.rule().conditionCount())
            .thenComparingLong(a -> -a.recency())
            .thenComparingLong(Activation::seq);

    private final TreeSet<Activation> queue = new TreeSet<>(ORDER);
    private final Map<String, Activation> byKey = new HashMap<>();
    private final Map<String, Set<Activation>> byFact = new HashMap<>();

    boolean contains(String key) {
        return byKey.containsKey(key);
    }

    void add(Activation a) {
        if (byKey.putIfAbsent(a.key(), a) != null) {
            return;
        }
        queue.add(a);
        for (String fact : a.binding().values()) {
            byFact.computeIfAbsent(fact, k -> new HashSet<>()).add(a);
        }
    }

    Optional<Activation> poll() {
        Activation a = queue.pollFirst();
        if (a != null) {
            forget(a);
        }
        return Optional.ofNullable(a);
    }

    /** Withdraws every activation that binds the fact. */
    void withdrawFact(String fact) {
        Set<Activation> as = byFact.remove(fact);
        if (as != null) {
            for (Activation a : List.copyOf(as)) {
                queue.remove(a);
                forget(a);
            }
        }
    }

    /** Withdraws every activation of the frame. */
    void withdrawRule(String frame) {
        for (Activation a : List.copyOf(queue)) {
            if (a.rule().frame().equals(frame)) {
                queue.remove(a);
                forget(a);
            }
        }
    }

    void clear() {
        queue.clear();
        byKey.clear();
        byFact.clear();
    }

    int size() {
        return queue.size();
    }

    /** The waiting activations in the order they would fire, copied. */
    List<Activation> inOrder() {
        return List.copyOf(queue);
    }

    private void forget(Activation a) {
        byKey.remove(a.key());
        for (String fact : a.binding().values()) {
            Set<Activation> s = byFact.get(fact);
            if (s != null) {
                s.remove(a);
                if (s.isEmpty()) {
                    byFact.remove(fact);
                }
            }
        }
    }
}
