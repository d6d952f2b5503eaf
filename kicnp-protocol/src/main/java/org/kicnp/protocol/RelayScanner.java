package org.kicnp.protocol;

import static java.nio.charset.StandardCharsets.UTF_8;

import java.util.Optional;

/**
 * The one-pass byte scanner behind {@link RelayRoute}: reads a relay's routing members without a JSON library and
 * without allocating anything but the few short strings it returns (names that repeat come from {@link NameCache}).
 * It accepts only a strict subset of JSON — one object whose members are strings (and {@code "v":1}), no escapes in
 * member names or in the routing members, well-formed UTF-8 and escapes in the subject and body — and gives
 * {@code null} for anything else, which then takes the general decoder's path. Whatever it accepts, the general
 * decoder decodes to the same relay. Not thread-safe: one per connection ({@link RelayRouteReader}) or per use
 * ({@link RelayRoute#scan}). A scanner that is used again remembers the last route it gave and gives that same
 * instance again when the next relay has the same routing members (an agent writing to the same peer again and
 * again, the common case): no route and no {@code Optional} per relay then.
 */
final class RelayScanner {
    private static final int ID = 0;
    private static final int FROM = 1;
    private static final int TO_AGENT = 2;
    private static final int TO_KIND = 3;
    private static final int SUBJECT = 4;
    private static final int BODY = 5;
    private static final int VERSION = 6;
    private static final int TYPE = 7;
    private static final byte[][] NAMES = {
        bytes("id"), bytes("from"), bytes("toAgent"), bytes("toKind"), bytes("subject"), bytes("body"), bytes("v"),
        bytes("type")
    };
    private static final byte[] RELAY = bytes("relay");

    private byte[] b;
    private int end;
    private int i;
    /** Where the last string scanned starts and ends (its content, without quotes), and whether it had escapes. */
    private int strStart;
    private int strEnd;
    private boolean escaped;
    /** The routing members' text, as scanned (fields rather than an array: one allocation fewer per relay). */
    private String id;
    private String from;
    private String toAgentName;
    private String toKindName;
    /** The route given last, given again when the next one is the same. */
    private RelayRoute last;

    /** The route of {@code payload[offset, offset + length)}, or {@code null} when it is not a relay this accepts. */
    RelayRoute scan(byte[] payload, int offset, int length) {
        this.b = payload;
        this.i = offset;
        this.end = offset + length;
        id = null;
        from = null;
        toAgentName = null;
        toKindName = null;
        RelayRoute route = scan();
        this.b = null; // holds no payload between uses
        return route;
    }

    private static byte[] bytes(String s) {
        return s.getBytes(UTF_8);
    }

    private RelayRoute scan() {
        int seen = 0;
        ws();
        if (!take('{')) {
            return null;
        }
        ws();
        if (peek() == '}') {
            return null;
        }
        while (true) {
            if (!string() || escaped) {
                return null;
            }
            int member = member();
            if (member < 0 || (seen & (1 << member)) != 0) {
                return null; // an unknown or repeated member
            }
            seen |= 1 << member;
            ws();
            if (!take(':')) {
                return null;
            }
            ws();
            if (member == VERSION) {
                if (!take('1') || peek() >= '0' && peek() <= '9' || peek() == '.' || peek() == 'e' || peek() == 'E') {
                    return null;
                }
            } else {
                if (!string()) {
                    return null;
                }
                if (member == TYPE) {
                    if (escaped || !equalsAt(RELAY)) {
                        return null;
                    }
                } else if (member != BODY && strEnd - strStart > Message.MAX_NAME_LENGTH) {
                    // A member that may be too long (never fewer bytes than characters): decoded in full, which says so.
                    return null;
                } else if (member <= TO_KIND) {
                    if (escaped) {
                        return null;
                    }
                    // Names repeat from relay to relay: answered from NameCache (the empty id of every
                    // fire-and-forget relay is the one empty string).
                    String t = member == ID && strEnd != strStart ? new String(b, strStart, strEnd - strStart, UTF_8)
                            : NameCache.of(b, strStart, strEnd);
                    switch (member) {
                        case ID -> id = t;
                        case FROM -> from = t;
                        case TO_AGENT -> toAgentName = t;
                        default -> toKindName = t;
                    }
                }
            }
            ws();
            if (take(',')) {
                ws();
            } else if (take('}')) {
                break;
            } else {
                return null;
            }
        }
        ws();
        int required = 1 << ID | 1 << FROM | 1 << SUBJECT | 1 << BODY | 1 << VERSION | 1 << TYPE;
        boolean toAgent = (seen & 1 << TO_AGENT) != 0;
        boolean toKind = (seen & 1 << TO_KIND) != 0;
        if (i != end || (seen & required) != required || toAgent == toKind) {
            return null;
        }
        RelayRoute before = last;
        if (before != null && before.id().equals(id) && before.from().equals(from)
                && (toAgent ? before.toAgent().isPresent() && before.toAgent().get().equals(toAgentName)
                        : before.toKind().isPresent() && before.toKind().get().name().equalsIgnoreCase(toKindName))) {
            return before;
        }
        Optional<AgentKind> kind = Optional.empty();
        if (toKind) {
            kind = kind(toKindName);
            if (kind.isEmpty()) {
                return null;
            }
        }
        last = new RelayRoute(id, from, Optional.ofNullable(toAgentName), kind);
        return last;
    }

    private static Optional<AgentKind> kind(String wire) {
        for (AgentKind k : AgentKind.values()) {
            if (k.name().equalsIgnoreCase(wire)) {
                return Optional.of(k);
            }
        }
        return Optional.empty();
    }

    private int member() {
        for (int m = 0; m < NAMES.length; m++) {
            if (equalsAt(NAMES[m])) {
                return m;
            }
        }
        return -1;
    }

    private boolean equalsAt(byte[] name) {
        if (strEnd - strStart != name.length) {
            return false;
        }
        for (int k = 0; k < name.length; k++) {
            if (b[strStart + k] != name[k]) {
                return false;
            }
        }
        return true;
    }

    private int peek() {
        return i < end ? b[i] & 0xFF : -1;
    }

    private boolean take(char c) {
        if (i < end && b[i] == c) {
            i++;
            return true;
        }
        return false;
    }

    private void ws() {
        while (i < end && (b[i] == ' ' || b[i] == '\n' || b[i] == '\r' || b[i] == '\t')) {
            i++;
        }
    }

    /** A JSON string at the cursor: checks escapes and UTF-8, and records where its content is. */
    private boolean string() {
        if (!take('"')) {
            return false;
        }
        strStart = i;
        escaped = false;
        while (i < end) {
            int c = b[i] & 0xFF;
            if (c == '"') {
                strEnd = i++;
                return true;
            }
            if (c < 0x20) {
                return false;
            }
            if (c == '\\') {
                escaped = true;
                if (!escape()) {
                    return false;
                }
            } else if (c < 0x80) {
                i++;
            } else if (!utf8(c)) {
                return false;
            }
        }
        return false;
    }

    private boolean escape() {
        if (i + 1 >= end) {
            return false;
        }
        int c = b[i + 1];
        if (c == '"' || c == '\\' || c == '/' || c == 'b' || c == 'f' || c == 'n' || c == 'r' || c == 't') {
            i += 2;
            return true;
        }
        if (c != 'u' || i + 5 >= end) {
            return false;
        }
        for (int k = i + 2; k < i + 6; k++) {
            if (Character.digit(b[k], 16) < 0) {
                return false;
            }
        }
        i += 6;
        return true;
    }

    /** One well-formed UTF-8 sequence of two to four bytes led by {@code lead} (no overlongs, no surrogates). */
    private boolean utf8(int lead) {
        int n;
        int lo = 0x80;
        int hi = 0xBF;
        if (lead >= 0xC2 && lead <= 0xDF) {
            n = 1;
        } else if (lead >= 0xE0 && lead <= 0xEF) {
            n = 2;
            lo = lead == 0xE0 ? 0xA0 : 0x80;
            hi = lead == 0xED ? 0x9F : 0xBF;
        } else if (lead >= 0xF0 && lead <= 0xF4) {
            n = 3;
            lo = lead == 0xF0 ? 0x90 : 0x80;
            hi = lead == 0xF4 ? 0x8F : 0xBF;
        } else {
            return false;
        }
        if (i + n >= end) {
            return false;
        }
        int second = b[i + 1] & 0xFF;
        if (second < lo || second > hi) {
            return false;
        }
        for (int k = i + 2; k <= i + n; k++) {
            if ((b[k] & 0xC0) != 0x80) {
                return false;
            }
        }
        i += n + 1;
        return true;
    }
}
