package org.kicnp.language;

import static java.util.Objects.requireNonNull;

import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;

/**
 * A verb of the lexicon with its case frame (valency): the cases it may take, those it needs, the particles that
 * may follow it ("sit down", "shake hands"), and the prepositions whose case differs from the lexicon's default
 * ("look at me": at marks the goal). Build with {@link #of}.
 *
 * @param lemma            the base form, as said in an imperative
 * @param action           the normalised predicate put in {@link Case#ACTION}
 * @param kind             how the verb's clause becomes an act
 * @param particles        words that may follow the verb as part of it
 * @param particleRequired whether one of the particles must follow ("shake" alone is not "shake hands")
 * @param allowed          the cases the verb takes (besides {@link Case#ACTION} and {@link Case#AGENT})
 * @param required         the cases it cannot do without
 * @param markers          prepositions whose case differs from the lexicon's default
 */
public record Verb(String lemma, String action, Kind kind, Set<String> particles, boolean particleRequired,
                   Set<Case> allowed, Set<Case> required, Map<String, Case> markers) {

    /** How a clause with this verb becomes an act. */
    public enum Kind {
        /** An imperative to a robot: sit, go, look, stop. */
        COMMAND,
        /** Moving a thing to someone (bring, give, fetch): with a drink and no robot named, a drink request. */
        TRANSFER,
        /** The speaker wanting something (want, like, have, take): with "I" as subject, a drink request. */
        WANT,
        /** The speaker repeating what they meant (meant, said): a drink request that corrects the last one. */
        CORRECT
    }

    public Verb {
        requireNonNull(lemma, "lemma");
        requireNonNull(action, "action");
        requireNonNull(kind, "kind");
        particles = Set.copyOf(particles);
        allowed = Set.copyOf(allowed);
        required = Set.copyOf(required);
        markers = Map.copyOf(markers);
        if (!allowed.containsAll(required)) {
            throw new IllegalArgumentException("Verb '" + lemma + "' requires cases it does not allow: " + required + ".");
        }
    }

    /** Starts a verb whose action is its lemma. */
    public static Builder of(String lemma, Kind kind) {
        return new Builder(lemma, kind);
    }

    /** Builds a {@link Verb}; every method returns this builder. */
    public static final class Builder {
        private final String lemma;
        private final Kind kind;
        private String action;
        private final Set<String> particles = new java.util.HashSet<>();
        private boolean particleRequired;
        private final Set<Case> allowed = EnumSet.noneOf(Case.class);
        private final Set<Case> required = EnumSet.noneOf(Case.class);
        private final Map<String, Case> markers = new LinkedHashMap<>();

        private Builder(String lemma, Kind kind) {
            this.lemma = lemma;
            this.kind = kind;
            this.action = lemma;
        }

        public Builder action(String a) {
            action = a;
            return this;
        }

        public Builder particles(String... words) {
            particles.addAll(Set.of(words));
            return this;
        }

        public Builder particleRequired() {
            particleRequired = true;
            return this;
        }

        public Builder allows(Case... cases) {
            allowed.addAll(Set.of(cases));
            return this;
        }

        public Builder requires(Case... cases) {
            allowed.addAll(Set.of(cases));
            required.addAll(Set.of(cases));
            return this;
        }

        public Builder marker(String preposition, Case c) {
            markers.put(preposition, c);
            return this;
        }

        public Verb build() {
            return new Verb(lemma, action, kind, particles, particleRequired, allowed, required, markers);
        }
    }
}
