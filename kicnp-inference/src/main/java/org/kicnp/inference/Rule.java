package org.kicnp.inference;

import java.util.List;
import java.util.Optional;

/**
 * A behavior frame compiled for matching: its required instance slots (which must all be bound to fire), its
 * optional instance slots (bound at firing when something fits), and what the agenda orders by: explicit
 * priority, depth in the hierarchy and number of conditions.
 */
record Rule(String frame, int priority, int depth, int conditionCount, List<SlotPattern> required,
            List<SlotPattern> optional) {
    Rule {
        required = List.copyOf(required);
        optional = List.copyOf(optional);
    }

    List<SlotPattern> patterns() {
        return java.util.stream.Stream.concat(required.stream(), optional.stream()).toList();
    }

    Optional<SlotPattern> pattern(String slot) {
        return patterns().stream().filter(p -> p.slot().equals(slot)).findFirst();
    }

    List<String> uniqueSlots() {
        return patterns().stream().filter(SlotPattern::unique).map(SlotPattern::slot).toList();
    }
}
