package org.kicnp.inference;

import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * A behavior frame compiled for matching: its required instance slots (which must all be bound to fire), its
 * optional instance slots (bound at firing when something fits), and what the agenda orders by: explicit
 * priority, depth in the hierarchy and number of conditions.
 */
record Rule(String frame, int priority, int depth, int conditionCount, List<SlotPattern> required,
            List<SlotPattern> optional, List<SlotPattern> patterns, List<String> uniqueSlots) {
    Rule {
        required = List.copyOf(required);
        optional = List.copyOf(optional);
        patterns = List.copyOf(patterns);
        uniqueSlots = List.copyOf(uniqueSlots);
    }

    /** A rule; {@code patterns} are the required then the optional slots, the unique ones are the required unique. */
    static Rule of(String frame, int priority, int depth, int conditionCount, List<SlotPattern> required,
                   List<SlotPattern> optional) {
        List<SlotPattern> all = Stream.concat(required.stream(), optional.stream()).toList();
        List<String> unique = required.stream().filter(SlotPattern::unique).map(SlotPattern::slot).toList();
        return new Rule(frame, priority, depth, conditionCount, required, optional, all, unique);
    }

    /** Rules are compared by identity: one compiled rule per frame version. */
    @Override public boolean equals(Object o) {
        return this == o;
    }

    @Override public int hashCode() {
        return System.identityHashCode(this);
    }

    Optional<SlotPattern> pattern(String slot) {
        return patterns().stream().filter(p -> p.slot().equals(slot)).findFirst();
    }
}
