package org.kicnp.language;

import static java.util.Objects.requireNonNull;

/**
 * What fills one case: the words as said, their semantic class, the normalised value behaviour frames match on
 * ({@code tea} for "a hot Tea", {@code speaker} for "me", {@code Scout} for "scout"), and whether the lexicon knows
 * it. Only a common noun missing from the lexicon is unknown: "I'd like a lemonade" gives {@code lemonade} with
 * {@code known == false}, so Robovie can say it has none. Proper names need no lexicon entry and are known.
 */
public record Filler(String text, SemanticClass semanticClass, String value, boolean known) {
    public Filler {
        requireNonNull(text, "text");
        requireNonNull(semanticClass, "semanticClass");
        requireNonNull(value, "value");
        if (value.isBlank()) {
            throw new IllegalArgumentException("A filler needs a value; '" + text + "' has none.");
        }
    }

    /** A filler the lexicon knows. */
    public static Filler known(String text, SemanticClass semanticClass, String value) {
        return new Filler(text, semanticClass, value, true);
    }
}
