package org.kicnp.inference;

import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.BiFunction;
import org.kicnp.core.Value;

/**
 * The instances that can fill one slot of one behavior frame (right class, constant conditions hold), with hash
 * indexes on the slot paths that equality joins look up, so a join reads only the partners that can match.
 */
final class AlphaMemory {
    private final Rule rule;
    private final SlotPattern pattern;
    private final LinkedHashSet<String> facts = new LinkedHashSet<>();
    private final Map<List<String>, Map<Value, Set<String>>> indexes = new HashMap<>();
    private final Map<String, Map<List<String>, Value>> keysOf = new HashMap<>();

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

    void addIndex(List<String> path) {
        indexes.putIfAbsent(List.copyOf(path), new HashMap<>());
    }

    boolean contains(String fact) {
        return facts.contains(fact);
    }

    Collection<String> facts() {
        return facts;
    }

    int size() {
        return facts.size();
    }

    /** Adds a fact, indexing it under the value each indexed path reaches from it. */
    void add(String fact, BiFunction<String, List<String>, Optional<Value>> pathValue) {
        if (!facts.add(fact)) {
            return;
        }
        for (Map.Entry<List<String>, Map<Value, Set<String>>> e : indexes.entrySet()) {
            Optional<Value> key = pathValue.apply(fact, e.getKey());
            if (key.isPresent()) {
                Value k = Values.key(key.get());
                e.getValue().computeIfAbsent(k, x -> new LinkedHashSet<>()).add(fact);
                keysOf.computeIfAbsent(fact, x -> new LinkedHashMap<>()).put(e.getKey(), k);
            }
        }
    }

    void remove(String fact) {
        if (!facts.remove(fact)) {
            return;
        }
        Map<List<String>, Value> keys = keysOf.remove(fact);
        if (keys != null) {
            keys.forEach((path, key) -> {
                Set<String> bucket = indexes.get(path).get(key);
                if (bucket != null) {
                    bucket.remove(fact);
                    if (bucket.isEmpty()) {
                        indexes.get(path).remove(key);
                    }
                }
            });
        }
    }

    /** The facts whose value along {@code path} equals {@code key}; the path must have been indexed. */
    Collection<String> lookup(List<String> path, Value key) {
        Map<Value, Set<String>> index = indexes.get(path);
        if (index == null) {
            throw new IllegalStateException("No index on " + path + " for slot '" + pattern.slot() + "'.");
        }
        return index.getOrDefault(Values.key(key), Set.of());
    }
}
