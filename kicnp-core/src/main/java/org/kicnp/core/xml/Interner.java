package org.kicnp.core.xml;

import java.util.HashMap;

/**
 * A per-load canonicalizing map for short strings. Slot names, type names, class names and frame references repeat
 * across thousands of frames; sharing one String for each keeps a large knowledge base small in memory.
 */
final class Interner {
    private static final int MAX_LENGTH = 64;
    private final HashMap<String, String> strings = new HashMap<>(1 << 16);

    String intern(String s) {
        if (s.length() > MAX_LENGTH) {
            return s;
        }
        String known = strings.putIfAbsent(s, s);
        return known == null ? s : known;
    }
}
