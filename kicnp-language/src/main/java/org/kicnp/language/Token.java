package org.kicnp.language;

/**
 * One word as the grammar sees it: {@code word} in lower case with contractions expanded, {@code surface} as
 * typed (for proper names), or a comma, which separates vocatives and discourse markers from the clause.
 */
record Token(String word, String surface) {
    static final Token COMMA = new Token(",", ",");

    boolean isComma() {
        return word.equals(",");
    }

    /** True if the speaker wrote it with a capital letter, as a proper name. */
    boolean capitalized() {
        return !surface.isEmpty() && Character.isUpperCase(surface.charAt(0));
    }

    /** Letters only (with inner hyphens or apostrophes): what a name or a noun may be made of. */
    boolean isAlphabetic() {
        if (word.isEmpty() || !Character.isLetter(word.charAt(0))) {
            return false;
        }
        for (int i = 1; i < word.length(); i++) {
            char c = word.charAt(i);
            if (!Character.isLetter(c) && c != '-' && c != '\'') {
                return false;
            }
        }
        return true;
    }

    @Override public String toString() {
        return word;
    }
}
