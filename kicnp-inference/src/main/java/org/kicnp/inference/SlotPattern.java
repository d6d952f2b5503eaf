package org.kicnp.inference;

import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.kicnp.core.Condition;

/**
 * One instance slot of a behavior frame as the match network sees it: the class it must hold, its condition, its
 * facets, whether the condition can be tested on the candidate alone ({@code alpha}), the other instance slots its
 * condition refers to ({@code joins}), and the equality join that a hash index can answer, if there is one.
 * {@code conditionText} is the condition's canonical text, made once for the explanations of every firing.
 */
record SlotPattern(int index, String slot, String argument, Condition condition, String conditionText,
                   boolean required, boolean shared, boolean unique, boolean alpha, Set<String> joins,
                   Optional<EqualityJoin> equality) {
    SlotPattern {
        joins = Set.copyOf(joins);
    }

    /**
     * {@code .left == head.rest}: the candidate's value along {@code left} equals the value reached from the
     * instance bound to slot {@code head} along {@code rest}.
     */
    record EqualityJoin(List<String> left, String head, List<String> rest) {
        EqualityJoin {
            left = List.copyOf(left);
            rest = List.copyOf(rest);
        }
    }

    /**
     * Whether what this slot holds is claimed: an unshared slot (its instance fills it once), or an optional unique
     * slot (the same instance never in this slot of two instances of the frame). Required unique slots form the
     * frame's key instead (see {@link Rule#uniqueSlots()}).
     */
    boolean claims() {
        return !shared || (unique && !required);
    }

    boolean isScript() {
        return condition instanceof Condition.Script;
    }
}
