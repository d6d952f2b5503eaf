package org.kicnp.inference;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
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
    private final List<List<String>> paths = new ArrayList<>(2);
    private final List<Map<Value, Set<String>>> indexes = new ArrayList<>(2);

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
        if (!paths.contains(path)) {
            paths.add(List.copyOf(path));
            indexes.add(new HashMap<>());
        }
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

    /**
     * Adds a fact, indexing it under the value each indexed path reaches from it; returns those keys, one per index
     * (null where the path reaches nothing), for the caller to keep and give back to {@link #remove}; null when there
     * are no indexes or the fact was there already.
     */
    Value[] add(String fact, BiFunction<String, List<String>, Optional<Value>> pathValue) {
        if (!facts.add(fact) || paths.isEmpty()) {
            return null;
        }
        Value[] keys = null;
        for (int i = 0; i < paths.size(); i++) {
            Optional<Value> key = pathValue.apply(fact, paths.get(i));
            if (key.isPresent()) {
                Value k = Values.key(key.get());
                Set<String> bucket = indexes.get(i).get(k);
                if (bucket == null) {
                    bucket = new LinkedHashSet<>(4);
                    indexes.get(i).put(k, bucket);
                }
                bucket.add(fact);
                if (keys == null) {
                    keys = new Value[paths.size()];
                }
                keys[i] = k;
            }
        }
        return keys;
    }

    /** Removes a fact filed under the keys {@link #add} returned for it. */
    void remove(String fact, Value[] keys) {
        if (!facts.remove(fact)) {
            return;
        }
        if (keys == null) {
            return;
        }
        for (int i = 0; i < keys.length; i++) {
            if (keys[i] == null) {
                continue;
            }
            Map<Value, Set<String>> index = indexes.get(i);
            Set<String> bucket = index.get(keys[i]);
            if (bucket != null) {
                bucket.remove(fact);
                if (bucket.isEmpty()) {
                    index.remove(keys[i]);
                }
            }
        }
    }

    /** The facts whose value along {@code path} equals {@code key}; the path must have been indexed. */
    Collection<String> lookup(List<String> path, Value key) {
        int i = paths.indexOf(path);
        if (i < 0) {
            throw new IllegalStateException("No index on " + path + " for slot '" + pattern.slot() + "'.");
        }
        return indexes.get(i).getOrDefault(Values.key(key), Set.of());
    }
}
