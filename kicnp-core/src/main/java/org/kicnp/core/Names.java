package org.kicnp.core;

/** Checks frame and slot names without regular expressions: loading a large knowledge base checks millions. */
final class Names {
    private Names() {
    }

    /** Letters, digits, '_' and '-', starting with a letter or '_'. */
    static boolean isFrameName(String s) {
        if (s.isEmpty() || !(Character.isLetter(s.charAt(0)) || s.charAt(0) == '_')) {
            return false;
        }
        for (int i = 1; i < s.length(); i++) {
            char c = s.charAt(i);
            if (!(Character.isLetterOrDigit(c) || c == '_' || c == '-')) {
                return false;
            }
        }
        return true;
    }

    /** Letters, digits, '_' and '$', starting with a letter, '_' or '$': what a script can read as s.name. */
    static boolean isSlotName(String s) {
        if (s.isEmpty() || !(Character.isLetter(s.charAt(0)) || s.charAt(0) == '_' || s.charAt(0) == '$')) {
            return false;
        }
        for (int i = 1; i < s.length(); i++) {
            char c = s.charAt(i);
            if (!(Character.isLetterOrDigit(c) || c == '_' || c == '$')) {
                return false;
            }
        }
        return true;
    }
}
