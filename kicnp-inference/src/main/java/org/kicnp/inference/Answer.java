package org.kicnp.inference;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;

/**
 * One answer of {@link InferenceEngine#ask}: an instance that exists, or one that could be derived, with the
 * instance slots it has or would have (slot → instance, "?Frame" for an instance that would itself be derived).
 */
public record Answer(String className, Optional<String> instance, Map<String, String> slots, Proof proof) {
    public Answer {
        slots = Map.copyOf(slots);
    }

    public boolean derivable() {
        return instance.isEmpty();
    }

    Map<String, Object> toScript() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("class", className);
        m.put("instance", instance.orElse(""));
        m.put("derivable", derivable());
        m.put("slots", Map.copyOf(slots));
        return m;
    }
}
