package org.kicnp.core.xml;

import java.util.HashMap;

/**
 * A per-load canonicalizing map for short strings. Slot names, type names, class names and frame references repeat
 * across thousands of frames; sharing one String for each keeps a large knowledge base small in memory. A small
 * direct-mapped table in front answers the strings seen most (the reader hands over the same String for a repeated
 * short text) without a map look-up.
 */
final class Interner {
    private static final int MAX_LENGTH = 64;
    private static final int RECENT = 1 << 10;
    private final HashMap<String, String> strings = new HashMap<>(1 << 16);
    private final String[] recent = new String[RECENT];

    String intern(String s) {
        if (s.length() > MAX_LENGTH) {
            return s;
        }
        int slot = s.hashCode() & RECENT - 1;
        String hit = recent[slot];
        if (hit != null && (hit == s || hit.equals(s))) {
            return hit;
        }
        String known = strings.putIfAbsent(s, s);
        String canonical = known == null ? s : known;
        recent[slot] = canonical;
        return canonical;
    }
}
