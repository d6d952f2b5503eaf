package org.kicnp.core;

import java.util.concurrent.ConcurrentHashMap;

/** Checks frame and slot names without regular expressions: loading a large knowledge base checks millions. */
final class Names {
    /** Past this many distinct slot names, new ones are no longer made canonical (the table stays bounded). */
    private static final int MAX_CANONICAL = 1 << 16;
    private static final ConcurrentHashMap<String, String> CANONICAL = new ConcurrentHashMap<>();

    private Names() {
    }

    /**
     * One String for each slot name: slots made of equal names, and the paths of conditions that name them, hold the
     * same String, so that looking a slot up along a path compares references (what {@code equals} tries first), not
     * characters. A knowledge base has a few hundred slot names and millions of slots.
     */
    static String canonical(String slotName) {
        String c = CANONICAL.get(slotName);
        if (c != null) {
            return c;
        }
        if (CANONICAL.size() >= MAX_CANONICAL) {
            return slotName;
        }
        c = CANONICAL.putIfAbsent(slotName, slotName);
        return c != null ? c : slotName;
    }

    /** Letters, digits, '_' and '-', starting with a letter or '_'. */
    static boolean isFrameName(String s) {
        if (s.isEmpty() || !(Character.isLetter(s.charAt(0)) || s.charAt(0) == '_')) {
            return false;
        }
        for (int i = 1; i < s.length(); i++) {
            char c = s.charAt(i);
            if (!(isAsciiLetterOrDigit(c) || c == '_' || c == '-' || c >= 128 && Character.isLetterOrDigit(c))) {
                return false;
            }
        }
        return true;
    }

    /**
     * A frame name made from any text, such as a person's name heard: each run of characters a frame name cannot hold
     * (spaces, apostrophes, combining marks, a letter beyond U+FFFF) becomes one '_', and a '_' goes first when the
     * text does not start with a letter. The same text always gives the same name; blank text gives "_".
     */
    static String toFrameName(String text) {
        StringBuilder sb = new StringBuilder(text.length() + 1);
        boolean gap = false;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (Character.isLetterOrDigit(c) || c == '_' || c == '-') {
                if (gap) {
                    sb.append('_');
                    gap = false;
                }
                sb.append(c);
            } else {
                gap = true;
            }
        }
        if (gap) {
            sb.append('_');
        }
        if (sb.isEmpty() || !(Character.isLetter(sb.charAt(0)) || sb.charAt(0) == '_')) {
            sb.insert(0, '_');
        }
        return sb.toString();
    }

    /** Letters, digits, '_' and '$', starting with a letter, '_' or '$': what a script can read as s.name. */
    static boolean isSlotName(String s) {
        if (s.isEmpty() || !(Character.isLetter(s.charAt(0)) || s.charAt(0) == '_' || s.charAt(0) == '$')) {
            return false;
        }
        for (int i = 1; i < s.length(); i++) {
            char c = s.charAt(i);
            if (!(isAsciiLetterOrDigit(c) || c == '_' || c == '$' || c >= 128 && Character.isLetterOrDigit(c))) {
                return false;
            }
        }
        return true;
    }

    /** {@link Character#isLetterOrDigit} for ASCII, without the Unicode tables: names are mostly ASCII. */
    private static boolean isAsciiLetterOrDigit(char c) {
        return c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z' || c >= '0' && c <= '9';
    }
}
