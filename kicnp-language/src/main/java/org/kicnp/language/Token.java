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
        return !surface.isEmpty() && Character.isUpperCase(surface.codePointAt(0));
    }

    /**
     * Letters only (with inner hyphens or apostrophes, and the marks that belong to letters, such as the vowel signs
     * of Devanagari): what a name or a noun may be made of.
     */
    boolean isAlphabetic() {
        if (word.isEmpty() || !Character.isLetter(word.codePointAt(0))) {
            return false;
        }
        for (int i = Character.charCount(word.codePointAt(0)); i < word.length(); ) {
            int c = word.codePointAt(i);
            if (!Character.isLetter(c) && !isMark(c) && c != '-' && c != '\'') {
                return false;
            }
            i += Character.charCount(c);
        }
        return true;
    }

    /** A combining mark, part of the letter before it. */
    static boolean isMark(int codePoint) {
        int type = Character.getType(codePoint);
        return type == Character.NON_SPACING_MARK || type == Character.COMBINING_SPACING_MARK
                || type == Character.ENCLOSING_MARK;
    }

    @Override public String toString() {
        return word;
    }
}
