package org.kicnp.protocol;

import static java.nio.charset.StandardCharsets.UTF_8;

/**
 * The routing names a hub reads from relays (sender, receiver, kind), answered from a small direct-mapped cache of
 * the strings made before: a hub relays between the same agents again and again, so after the first message each
 * name is a cache hit and costs no allocation (before, two strings and their byte arrays per relay, about a quarter
 * of what the gateway allocated per message). Only ASCII names are cached; others are made each time. Shared by
 * threads without locks: a slot holds an immutable {@link String} (safely published through its final fields), and
 * a lost race only costs a string made again.
 */
final class NameCache {
    private static final int SLOTS = 4096;
    private static final int MAX_CACHED_LENGTH = 64;
    private static final String[] CACHE = new String[SLOTS];

    private NameCache() {
    }

    /** The string of the UTF-8 bytes {@code b[from, to)}: a cached equal string, or a new one. */
    static String of(byte[] b, int from, int to) {
        int length = to - from;
        if (length == 0) {
            return "";
        }
        if (length > MAX_CACHED_LENGTH) {
            return new String(b, from, length, UTF_8);
        }
        int h = 0;
        for (int k = from; k < to; k++) {
            int c = b[k];
            if (c < 0) {
                return new String(b, from, length, UTF_8); // not ASCII: not cached
            }
            h = 31 * h + c;
        }
        int slot = (h ^ h >>> 16) & (SLOTS - 1);
        String cached = CACHE[slot];
        if (cached != null && cached.hashCode() == h && sameAscii(cached, b, from, length)) {
            return cached;
        }
        String made = new String(b, from, length, UTF_8);
        CACHE[slot] = made;
        return made;
    }

    private static boolean sameAscii(String s, byte[] b, int from, int length) {
        if (s.length() != length) {
            return false;
        }
        for (int k = 0; k < length; k++) {
            if (s.charAt(k) != b[from + k]) {
                return false;
            }
        }
        return true;
    }
}
