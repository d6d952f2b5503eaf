package org.kicnp.protocol;

import static java.util.Objects.requireNonNull;

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

    /**
     * Scans a payload in one pass (see {@link RelayScanner}). The subject and body are checked to be well-formed
     * strings but not turned into {@code String}s. Anything that is not a plain relay — another type, another
     * version, a missing, repeated, unknown or mistyped member, an unknown kind, escapes in a member name or in a
     * routing member, broken JSON or UTF-8 — gives empty: the caller then decodes the payload in full, which accepts
     * it (ignoring unknown members) or says what is wrong.
     */
    static Optional<RelayRoute> scan(byte[] payload, int offset, int length) {
        java.util.Objects.checkFromIndexSize(offset, length, payload.length);
        return Optional.ofNullable(new RelayScanner().scan(payload, offset, length));
    }
}
