package org.kicnp.core.xml;

/**
 * Canonical Strings for short element texts, looked up by their characters, so the reading thread builds no new
 * String for text it has just seen: slot names, type names, TRUE and FALSE, class names in ISA and ARGUMENT. A
 * direct-mapped table: a text that misses replaces what was in its place, so texts seen once (most values) cost a
 * hash and nothing more. Confined to the thread that reads.
 */
final class TextCache {
    private static final int MAX_LENGTH = 32;
    private static final int SIZE = 1 << 12;

    private final String[] table = new String[SIZE];

    /** The text of {@code length} characters at {@code start} of {@code chars}, shared where it was seen before. */
    String text(char[] chars, int start, int length) {
        if (length > MAX_LENGTH) {
            return new String(chars, start, length);
        }
        int h = 0;
        for (int i = start, end = start + length; i < end; i++) {
            h = 31 * h + chars[i];
        }
        int slot = (h ^ h >>> 12) & SIZE - 1;
        String known = table[slot];
        if (known != null && matches(known, chars, start, length)) {
            return known;
        }
        String s = new String(chars, start, length);
        table[slot] = s;
        return s;
    }

    private static boolean matches(String s, char[] chars, int start, int length) {
        if (s.length() != length) {
            return false;
        }
        for (int i = 0; i < length; i++) {
            if (s.charAt(i) != chars[start + i]) {
                return false;
            }
        }
        return true;
    }
}
