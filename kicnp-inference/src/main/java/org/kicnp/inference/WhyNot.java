package org.kicnp.inference;

import static java.util.Objects.requireNonNull;

import java.util.Collections;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.StringJoiner;

/**
 * The answer to "why has this behavior frame not fired?" ({@link InferenceEngine#whyNot}), the question a rule
 * engine's users ask most after "why did it fire?". For each required slot, the instances that could fill it and
 * those its own condition turns away; then every binding of the remaining candidates (up to the engine's answer
 * limit), each with what stops it from firing now, checked in the order forward chaining checks: the slots'
 * declarative conditions, then refraction and what unshared or unique slots hold, then the agenda. Read-only: no
 * script runs and nothing is created, so a slot's script condition is named, not evaluated.
 *
 * @param frame     the behavior frame asked about
 * @param slots     its required instance slots, in order, with their candidates
 * @param bindings  the bindings of the candidates, each with its outcome
 * @param truncated whether there were more bindings than the engine's answer limit ({@link EngineOptions#maxAnswers})
 */
public record WhyNot(String frame, List<SlotCandidates> slots, List<Verdict> bindings, boolean truncated) {
    public WhyNot {
        requireNonNull(frame, "frame");
        slots = List.copyOf(slots);
        bindings = List.copyOf(bindings);
    }

    /**
     * One required slot: the class it needs, its condition's text ({@code COND_ANY} when it has none), the instances
     * that could fill it, and those its condition rejects on their own ("name: why"), which no binding uses. Each
     * list holds at most the engine's answer limit; the counts say how many there are.
     */
    public record SlotCandidates(String slot, String argument, String condition, List<String> candidates,
                                 List<String> rejected, int candidateCount, int rejectedCount) {
        public SlotCandidates {
            candidates = List.copyOf(candidates);
            rejected = List.copyOf(rejected);
            if (candidateCount < candidates.size() || rejectedCount < rejected.size()) {
                throw new IllegalArgumentException("A count is smaller than its list.");
            }
        }
    }

    /** What became of one binding (slot → instance, in slot order). */
    public record Verdict(Map<String, String> binding, Outcome outcome, String reason) {
        public Verdict {
            binding = Collections.unmodifiableMap(new LinkedHashMap<>(binding));
        }
    }

    /** Why a binding does not fire now, or that it will. */
    public enum Outcome {
        /** A declarative condition of a slot is false for it. */
        CONDITION_FALSE("fails a condition"),
        /** It fired already (refraction), or an unshared or unique slot's instance is held by an earlier firing. */
        BLOCKED("blocked"),
        /** It is on the agenda and fires when its turn comes. */
        WAITING("waiting on the agenda"),
        /** Nothing declarative stops it, but a script condition is false for it or its script fails (whyNot runs it). */
        SCRIPT_CONDITION("fails a script condition"),
        /**
         * Nothing whyNot can see stops it, yet it is not on the agenda: the engine has not matched it (its reason says
         * why when a script condition that holds now did not when the binding was matched). Not expected otherwise once
         * the engine has processed its changes (whyNot processes them first); reported rather than hidden.
         */
        WOULD_FIRE("not matched yet");

        private final String phrase;

        Outcome(String phrase) {
            this.phrase = phrase;
        }

        /** How the outcome reads in a sentence, of one binding. */
        public String phrase() {
            return phrase;
        }

        /** How the outcome reads after a count of bindings ("2 fail a condition"). */
        public String phrase(int count) {
            return count == 1 || !phrase.startsWith("fails ") ? phrase : "fail " + phrase.substring("fails ".length());
        }
    }

    /** One sentence: which slot has nothing to fill it, or how many bindings there are and what became of them. */
    public String summary() {
        for (SlotCandidates s : slots) {
            if (s.candidateCount() == 0) {
                int n = s.rejectedCount();
                String why = n == 0
                        ? "there is no instance of '" + s.argument() + "'"
                        : n + " instance" + (n == 1 ? " of '" : "s of '") + s.argument() + "' exist" + (n == 1 ? "s" : "")
                                + " but its condition " + s.condition() + " turns " + (n == 1 ? "it" : "them all")
                                + " away";
                return "'" + frame + "' cannot fire: nothing can fill its slot '" + s.slot() + "' (" + why + ").";
            }
        }
        if (bindings.isEmpty()) {
            return "'" + frame + "' cannot fire: its slots could only be filled by one instance in two slots.";
        }
        Map<Outcome, Integer> counts = new EnumMap<>(Outcome.class);
        for (Verdict v : bindings) {
            counts.merge(v.outcome(), 1, Integer::sum);
        }
        StringJoiner parts = new StringJoiner(", ");
        counts.forEach((o, n) -> parts.add(n + " " + o.phrase(n)));
        return "'" + frame + "' has " + (truncated ? "more than " : "") + bindings.size() + " binding"
                + (bindings.size() == 1 ? "" : "s") + ": " + parts + ".";
    }
}
