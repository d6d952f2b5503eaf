package org.kicnp.inference;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * Why a derived instance exists: the behavior frame that made it, the binding (slot → instance), each condition with
 * the value it was tested on, the firing number, the fact whose arrival completed the binding ({@code trigger}), and,
 * for an instance a script created, the instance whose firing ran that script. The binding is immutable and keeps
 * the order it was given in (the behavior frame's slot order for a firing).
 */
public record Derivation(String instance, String frame, Map<String, String> binding, List<CheckedCondition> conditions,
                         long firing, String trigger, Optional<String> createdBy) {
    public Derivation {
        requireNonNull(instance, "instance");
        requireNonNull(frame, "frame");
        binding = Binding.copyOf(binding);
        // A firing's own list is immutable already, and copying it would make every record it defers at once.
        conditions = conditions instanceof CheckedConditions ? conditions : List.copyOf(conditions);
        requireNonNull(trigger, "trigger");
        requireNonNull(createdBy, "createdBy");
    }

    /** The instances this one rests on: its binding, and the creating instance for a scripted creation. */
    List<String> supports() {
        List<String> out = new ArrayList<>(binding.values());
        createdBy.ifPresent(out::add);
        return out;
    }

    /** A slot condition as it was tested when the frame fired. */
    public record CheckedCondition(String slot, String condition, String value) { }
}
