package org.kicnp.inference;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import org.kicnp.core.InstanceShape;
import org.kicnp.core.KnowledgeBase;

/**
 * A behavior frame compiled for matching: its required instance slots (which must all be bound to fire), its
 * optional instance slots (bound at firing when something fits), and what the agenda orders by: explicit
 * priority, depth in the hierarchy and number of conditions. {@code claims}: some slot is unshared or unique, so a
 * binding may be blocked by what earlier firings hold. {@code scripted}: some slot has a script condition.
 * {@code onInstantiate}, {@code onDestroy}: the frame's scripts, as its instances inherit them (resolved when the
 * rule is compiled; an edit of the frame recompiles the rule; kept so that instances removed together with their
 * frame still get their {@code onDestroy}). {@code requiredSlots}:
 * the required slots' names in order, the keys of every binding the rule fires with ({@link Binding}).
 * {@code shape}: the frame's instances with those slots in that order, prepared for the knowledge base
 * ({@link KnowledgeBase#addInstance}): a firing that binds no optional slot adds its instance through it.
 */
record Rule(String frame, int priority, int depth, int conditionCount, List<SlotPattern> required,
            List<SlotPattern> optional, List<SlotPattern> patterns, List<String> uniqueSlots, boolean claims,
            boolean scripted, Optional<String> onInstantiate, Optional<String> onDestroy, List<String> requiredSlots,
            InstanceShape shape) {
    Rule {
        required = List.copyOf(required);
        requiredSlots = List.copyOf(requiredSlots);
        if (!shape.className().equals(frame) || shape.templates().size() != requiredSlots.size()) {
            throw new IllegalArgumentException("Rule " + frame + ": " + shape + " for the required slots "
                    + requiredSlots + ".");
        }
        optional = List.copyOf(optional);
        patterns = List.copyOf(patterns);
        uniqueSlots = List.copyOf(uniqueSlots);
        requireNonNull(onInstantiate, "onInstantiate");
        requireNonNull(onDestroy, "onDestroy");
    }

    /** A rule; {@code patterns} are the required then the optional slots, the unique ones are the required unique. */
    static Rule of(String frame, int priority, int depth, int conditionCount, List<SlotPattern> required,
                   List<SlotPattern> optional, Optional<String> onInstantiate) {
        return of(frame, priority, depth, conditionCount, required, optional, onInstantiate, Optional.empty());
    }

    /** As above, with the frame's {@code onDestroy} script as its instances inherit it. */
    static Rule of(String frame, int priority, int depth, int conditionCount, List<SlotPattern> required,
                   List<SlotPattern> optional, Optional<String> onInstantiate, Optional<String> onDestroy) {
        List<SlotPattern> all = Stream.concat(required.stream(), optional.stream()).toList();
        List<String> unique = required.stream().filter(SlotPattern::unique).map(SlotPattern::slot).toList();
        boolean claims = !unique.isEmpty() || all.stream().anyMatch(SlotPattern::claims);
        boolean scripted = all.stream().anyMatch(SlotPattern::isScript);
        List<String> slots = required.stream().map(SlotPattern::slot).toList();
        return new Rule(frame, priority, depth, conditionCount, required, optional, all, unique, claims, scripted,
                onInstantiate, onDestroy, slots, InstanceShape.of(frame, slots));
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
