package org.kicnp.inference;

import java.util.Map;

/**
 * A complete binding of a behavior frame's required slots, waiting on the agenda to fire. {@code recency} is the
 * assertion stamp of the newest fact in the binding; {@code seq} orders activations made at the same moment.
 */
record Activation(Rule rule, Map<String, String> binding, long recency, long seq) {
    Activation {
        binding = Map.copyOf(binding);
    }

    /** Activations are told apart by their sequence number, which is unique per engine. */
    @Override public boolean equals(Object o) {
        return o instanceof Activation a && a.seq == seq;
    }

    @Override public int hashCode() {
        return Long.hashCode(seq);
    }

    /** The refraction key: the frame and its binding, in slot order. */
    String key() {
        return key(rule.frame(), rule, binding);
    }

    static String key(String frame, Rule rule, Map<String, String> binding) {
        StringBuilder sb = new StringBuilder(frame);
        for (SlotPattern p : rule.required()) {
            sb.append('\u0000').append(binding.get(p.slot()));
        }
        return sb.toString();
    }
}
