package org.kicnp.protocol;

import static java.util.Objects.requireNonNull;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import java.io.IOException;
import java.util.Optional;

/**
 * What a hub needs to route a {@code relay} without decoding its text: the correlation id, the sender the message
 * names, and its one destination (an agent or a kind). Read by {@link MessageCodec#relayRoute} from a payload that
 * is a <em>plain</em> relay: valid JSON, version {@value MessageCodec#VERSION}, every required member once, each a
 * string (the kind one the protocol names), and no other member. Such a payload decodes to exactly the {@link Message.Relay} its
 * route describes, so when {@link #from()} already names the authenticated sender a hub may forward the payload's
 * bytes unchanged instead of decoding and re-encoding it.
 *
 * @param id the relay's correlation id, which the hub's {@code ack} echoes
 * @param from the sender named in the payload
 * @param toAgent the receiving agent's name, when sent to one agent
 * @param toKind the receiving agents' kind, when sent to every agent of a kind
 */
public record RelayRoute(String id, String from, Optional<String> toAgent, Optional<AgentKind> toKind) {
    public RelayRoute {
        requireNonNull(id, "id");
        requireNonNull(from, "from");
        requireNonNull(toAgent, "toAgent");
        requireNonNull(toKind, "toKind");
        if (toAgent.isPresent() == toKind.isPresent()) {
            throw new IllegalArgumentException("A relay route needs exactly one of toAgent and toKind.");
        }
    }

    private static final int ID = 0;
    private static final int FROM = 1;
    private static final int TO_AGENT = 2;
    private static final int TO_KIND = 3;
    private static final int SUBJECT = 4;
    private static final int BODY = 5;

    /**
     * Scans a payload in one streaming pass. The subject and body are checked to be well-formed strings but not
     * turned into {@code String}s. Anything that is not a plain relay — another type, another version, a missing,
     * repeated, unknown or mistyped member, an unknown kind, broken JSON — gives empty: the
     * caller then decodes the payload in full, which accepts it (ignoring unknown members) or says what is wrong.
     */
    static Optional<RelayRoute> scan(JsonFactory json, byte[] payload, int offset, int length) {
        try (JsonParser p = json.createParser(payload, offset, length)) {
            if (p.nextToken() != JsonToken.START_OBJECT) {
                return Optional.empty();
            }
            boolean version = false;
            boolean typed = false;
            boolean[] seen = new boolean[6];
            String[] text = new String[4];
            JsonToken t;
            while ((t = p.nextToken()) == JsonToken.FIELD_NAME) {
                String name = p.currentName();
                JsonToken value = p.nextToken();
                int member = member(name);
                if (member == -2) {
                    if (version || value != JsonToken.VALUE_NUMBER_INT
                            || p.getNumberType() != JsonParser.NumberType.INT || p.getIntValue() != MessageCodec.VERSION) {
                        return Optional.empty();
                    }
                    version = true;
                } else if (member == -3) {
                    if (typed || value != JsonToken.VALUE_STRING || !p.getText().equals("relay")) {
                        return Optional.empty();
                    }
                    typed = true;
                } else if (member < 0 || seen[member] || value != JsonToken.VALUE_STRING) {
                    return Optional.empty();
                } else {
                    seen[member] = true;
                    if (member < text.length) {
                        text[member] = p.getText();
                    } else {
                        p.getTextCharacters(); // decodes (and so checks) the string without making a String
                    }
                }
            }
            if (t != JsonToken.END_OBJECT || p.nextToken() != null || !version || !typed
                    || !seen[ID] || !seen[FROM] || !seen[SUBJECT] || !seen[BODY] || seen[TO_AGENT] == seen[TO_KIND]) {
                return Optional.empty();
            }
            Optional<AgentKind> kind = Optional.empty();
            if (seen[TO_KIND]) {
                kind = kind(text[TO_KIND]);
                if (kind.isEmpty()) {
                    return Optional.empty();
                }
            }
            return Optional.of(new RelayRoute(text[ID], text[FROM], Optional.ofNullable(text[TO_AGENT]), kind));
        } catch (IOException | RuntimeException e) {
            return Optional.empty();
        }
    }

    /** A kind as the wire writes it (any case, as the full decoder accepts). */
    private static Optional<AgentKind> kind(String wire) {
        for (AgentKind k : AgentKind.values()) {
            if (k.name().equalsIgnoreCase(wire)) {
                return Optional.of(k);
            }
        }
        return Optional.empty();
    }

    /** The index of a relay member, -2 for {@code v}, -3 for {@code type}, -1 for anything else. */
    private static int member(String name) {
        return switch (name) {
            case "id" -> ID;
            case "from" -> FROM;
            case "toAgent" -> TO_AGENT;
            case "toKind" -> TO_KIND;
            case "subject" -> SUBJECT;
            case "body" -> BODY;
            case "v" -> -2;
            case "type" -> -3;
            default -> -1;
        };
    }
}
