package org.kicnp.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.core.JacksonException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.MapperFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.cfg.EnumFeature;
import com.fasterxml.jackson.databind.json.JsonMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.fasterxml.jackson.datatype.jdk8.Jdk8Module;
import java.io.IOException;
import java.lang.reflect.RecordComponent;
import java.util.Optional;

/**
 * Turns a {@link Message} into the JSON payload of one frame and back (the length prefix is {@link Framing}'s job).
 * Decoding validates everything at the edge — JSON syntax, the version, the type, required members, member types —
 * and reports what is wrong as a {@link ProtocolException} carrying the code to answer with. Thread-safe.
 */
public final class MessageCodec {
    /** The protocol version this codec speaks, the value of {@code "v"}. */
    public static final int VERSION = 1;

    private final ObjectMapper mapper = JsonMapper.builder()
            .addModule(new Jdk8Module())
            .addModule(ValueJson.module())
            .configure(EnumFeature.WRITE_ENUMS_TO_LOWERCASE, true)
            .configure(MapperFeature.ACCEPT_CASE_INSENSITIVE_ENUMS, true)
            .configure(MapperFeature.ALLOW_COERCION_OF_SCALARS, false)
            .configure(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES, false)
            .configure(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES, true)
            .configure(DeserializationFeature.FAIL_ON_TRAILING_TOKENS, true)
            // An enumerated member is one of its lower-case names; a number would be read as an index ("stage": 3 as
            // failed), a member of the wrong JSON type taken silently.
            .configure(DeserializationFeature.FAIL_ON_NUMBERS_FOR_ENUMS, true)
            // A number or boolean where the protocol wants a string (an id, a name, a frame) is a member of the wrong
            // JSON type, as the relay's own reader says; data binding would otherwise take 9 for "9".
            .withCoercionConfig(com.fasterxml.jackson.databind.type.LogicalType.Textual, c -> c
                    .setCoercion(com.fasterxml.jackson.databind.cfg.CoercionInputShape.Integer,
                            com.fasterxml.jackson.databind.cfg.CoercionAction.Fail)
                    .setCoercion(com.fasterxml.jackson.databind.cfg.CoercionInputShape.Float,
                            com.fasterxml.jackson.databind.cfg.CoercionAction.Fail)
                    .setCoercion(com.fasterxml.jackson.databind.cfg.CoercionInputShape.Boolean,
                            com.fasterxml.jackson.databind.cfg.CoercionAction.Fail))
            // Nor a fraction where it wants a whole number (a sensor's ttlMs of 2.5 would be read as 2).
            .withCoercionConfig(com.fasterxml.jackson.databind.type.LogicalType.Integer, c -> c
                    .setCoercion(com.fasterxml.jackson.databind.cfg.CoercionInputShape.Float,
                            com.fasterxml.jackson.databind.cfg.CoercionAction.Fail))
            .serializationInclusion(JsonInclude.Include.NON_ABSENT)
            .build();

    /** Encodes a message as the UTF-8 JSON payload of one frame, envelope first. */
    public byte[] encode(Message message) {
        switch (message) {
            case Message.Relay r -> {
                return relay(r); // the hub's hot path: a relay and its ack per message relayed
            }
            case Message.Ack a -> {
                return ack(a);
            }
            default -> { }
        }
        MessageType type = MessageType.of(message);
        byte[] members;
        try {
            members = mapper.writeValueAsBytes(message); // {"id":...,...}: the record's own members
        } catch (JacksonException e) {
            throw new IllegalStateException("Could not encode a '" + type.wireName() + "' message.", e);
        }
        // The envelope, then the members, spliced as bytes: no intermediate tree (this is the relay hot path).
        byte[] head = ENVELOPES.get(type);
        boolean empty = members.length <= 2;
        byte[] out = new byte[head.length + (empty ? 1 : members.length)];
        System.arraycopy(head, 0, out, 0, head.length);
        if (empty) {
            out[head.length] = '}';
        } else {
            out[head.length] = ',';
            System.arraycopy(members, 1, out, head.length + 1, members.length - 1);
        }
        return out;
    }

    /** A relay written with the streaming generator: the same bytes data binding gives, at a fraction of the cost. */
    private byte[] relay(Message.Relay r) {
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream(64 + r.body().length() + r.subject().length());
        try (com.fasterxml.jackson.core.JsonGenerator g = mapper.getFactory().createGenerator(out)) {
            envelope(g, MessageType.RELAY);
            g.writeStringField("id", r.id());
            g.writeStringField("from", r.from());
            if (r.toAgent().isPresent()) {
                g.writeStringField("toAgent", r.toAgent().get());
            }
            if (r.toKind().isPresent()) {
                g.writeStringField("toKind", r.toKind().get().name().toLowerCase(java.util.Locale.ROOT));
            }
            g.writeStringField("subject", r.subject());
            g.writeStringField("body", r.body());
            g.writeEndObject();
        } catch (IOException e) {
            throw new IllegalStateException("Could not encode a 'relay' message.", e);
        }
        return out.toByteArray();
    }

    private byte[] ack(Message.Ack a) {
        String id = a.id();
        if (printableAscii(id)) { // the usual id: the generator's bytes, without a generator
            byte[] out = new byte[ACK_HEAD.length + id.length() + 2];
            System.arraycopy(ACK_HEAD, 0, out, 0, ACK_HEAD.length);
            id.getBytes(0, id.length(), out, ACK_HEAD.length);
            out[out.length - 2] = '"';
            out[out.length - 1] = '}';
            return out;
        }
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream(48 + a.id().length());
        try (com.fasterxml.jackson.core.JsonGenerator g = mapper.getFactory().createGenerator(out)) {
            envelope(g, MessageType.ACK);
            g.writeStringField("id", a.id());
            g.writeEndObject();
        } catch (IOException e) {
            throw new IllegalStateException("Could not encode an 'ack' message.", e);
        }
        return out.toByteArray();
    }

    private static final byte[] ACK_HEAD = ("{\"v\":" + VERSION + ",\"type\":\"ack\",\"id\":\"")
            .getBytes(java.nio.charset.StandardCharsets.US_ASCII);

    /** Whether JSON writes {@code s} as it is: printable ASCII without quote or backslash, so nothing is escaped. */
    private static boolean printableAscii(String s) {
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c < 0x20 || c > 0x7E || c == '"' || c == '\\') {
                return false;
            }
        }
        return true;
    }

    private static void envelope(com.fasterxml.jackson.core.JsonGenerator g, MessageType type) throws IOException {
        g.writeStartObject();
        g.writeNumberField("v", VERSION);
        g.writeStringField("type", type.wireName());
    }

    /** {@code {"v":1,"type":"NAME"} without its closing brace, per message type. */
    private static final java.util.Map<MessageType, byte[]> ENVELOPES = envelopes();

    private static java.util.Map<MessageType, byte[]> envelopes() {
        java.util.Map<MessageType, byte[]> m = new java.util.EnumMap<>(MessageType.class);
        for (MessageType t : MessageType.values()) {
            m.put(t, ("{\"v\":" + VERSION + ",\"type\":\"" + t.wireName() + "\"")
                    .getBytes(java.nio.charset.StandardCharsets.UTF_8));
        }
        return m;
    }

    /**
     * The route of a payload that is a plain relay (see {@link RelayRoute}), read without decoding its subject and
     * body; empty for any other payload, which {@link #decode} then handles.
     */
    public Optional<RelayRoute> relayRoute(byte[] payload, int offset, int length) {
        return RelayRoute.scan(payload, offset, length);
    }

    /**
     * Decodes the payload of one frame.
     *
     * @throws ProtocolException with {@link ErrorCode#BAD_JSON}, {@link ErrorCode#UNSUPPORTED_VERSION},
     *     {@link ErrorCode#UNKNOWN_TYPE} or {@link ErrorCode#BAD_MESSAGE}, and a sentence saying what is wrong
     */
    public Message decode(byte[] payload) {
        Message.Relay relay = plainRelay(payload);
        if (relay != null) {
            return relay;
        }
        JsonNode root = readTree(payload);
        JsonNode v = root.get("v");
        if (v == null || !v.isIntegralNumber() || !v.canConvertToLong() || v.asLong() != VERSION) {
            throw new ProtocolException(ErrorCode.UNSUPPORTED_VERSION,
                    "Protocol version " + (v == null ? "(missing)" : v.toString()) + " is not supported; this server speaks "
                            + VERSION + ".");
        }
        JsonNode t = root.get("type");
        String typeName = t != null && t.isTextual() ? t.textValue() : String.valueOf(t);
        MessageType type = MessageType.fromWireName(typeName).orElseThrow(() -> new ProtocolException(
                ErrorCode.UNKNOWN_TYPE, "Unknown message type '" + typeName + "'."));
        ObjectNode body = (ObjectNode) root;
        body.remove("v");
        body.remove("type");
        requireMembers(type, body);
        if (type == MessageType.RELAY) {
            return relay(body); // the hub's hot path: read straight from the tree, without data binding
        }
        try {
            return mapper.treeToValue(body, type.recordClass());
        } catch (JacksonException | IllegalArgumentException e) {
            throw new ProtocolException(ErrorCode.BAD_MESSAGE,
                    "Bad '" + typeName + "' message: " + member(e) + rootMessage(e), e);
        }
    }

    /** "the member 'args.speed': " for a member data binding refused, so the agent learns which; else nothing. */
    private static String member(Exception e) {
        if (!(e instanceof com.fasterxml.jackson.databind.JsonMappingException m) || m.getPath().isEmpty()) {
            return "";
        }
        StringBuilder path = new StringBuilder();
        for (com.fasterxml.jackson.databind.JsonMappingException.Reference r : m.getPath()) {
            if (r.getFieldName() != null) {
                path.append(path.isEmpty() ? "" : ".").append(r.getFieldName());
            } else if (r.getIndex() >= 0) {
                path.append('[').append(r.getIndex()).append(']');
            }
        }
        return path.isEmpty() ? "" : "the member '" + path + "': ";
    }

    private JsonNode readTree(byte[] payload) {
        JsonNode root;
        try {
            root = mapper.readTree(payload);
        } catch (IOException e) {
            throw new ProtocolException(ErrorCode.BAD_JSON, "The frame is not valid JSON: " + rootMessage(e), e);
        }
        if (root == null || !root.isObject()) {
            throw new ProtocolException(ErrorCode.BAD_JSON, "The frame must hold one JSON object.");
        }
        return root;
    }

    private static void requireMembers(MessageType type, ObjectNode body) {
        for (String name : REQUIRED.get(type)) {
            JsonNode member = body.get(name);
            if (member == null || member.isNull()) {
                throw new ProtocolException(ErrorCode.BAD_MESSAGE,
                        "A '" + type.wireName() + "' message needs the member '" + name + "'.");
            }
        }
    }

    /** The required (non-{@code Optional}) members of each type, looked up once rather than per message. */
    private static final java.util.Map<MessageType, java.util.List<String>> REQUIRED = required();

    private static java.util.Map<MessageType, java.util.List<String>> required() {
        java.util.Map<MessageType, java.util.List<String>> m = new java.util.EnumMap<>(MessageType.class);
        for (MessageType t : MessageType.values()) {
            m.put(t, java.util.Arrays.stream(t.recordClass().getRecordComponents())
                    .filter(c -> c.getType() != Optional.class).map(RecordComponent::getName).toList());
        }
        return m;
    }

    /**
     * The hub's hot path: a well-formed relay read in one streaming pass, without a tree. Anything else — another
     * type, a wrong version, a missing member, a member of the wrong JSON type, broken JSON — gives {@code null}
     * (the one internal use of null), and the general path decodes the payload or says what is wrong with it.
     */
    private Message.Relay plainRelay(byte[] payload) {
        try (com.fasterxml.jackson.core.JsonParser p = mapper.getFactory().createParser(payload)) {
            if (p.nextToken() != com.fasterxml.jackson.core.JsonToken.START_OBJECT) {
                return null;
            }
            long v = -1;
            boolean typed = false;
            String[] m = new String[RELAY_MEMBERS.size()];
            com.fasterxml.jackson.core.JsonToken t;
            while ((t = p.nextToken()) == com.fasterxml.jackson.core.JsonToken.FIELD_NAME) {
                String name = p.currentName();
                com.fasterxml.jackson.core.JsonToken value = p.nextToken();
                int member = RELAY_MEMBERS.indexOf(name);
                if (name.equals("v")) {
                    if (value != com.fasterxml.jackson.core.JsonToken.VALUE_NUMBER_INT) {
                        return null;
                    }
                    v = p.getLongValue();
                } else if (name.equals("type")) {
                    if (value != com.fasterxml.jackson.core.JsonToken.VALUE_STRING || !p.getText().equals("relay")) {
                        return null;
                    }
                    typed = true;
                } else if (member >= 0) {
                    if (value == com.fasterxml.jackson.core.JsonToken.VALUE_STRING) {
                        m[member] = p.getText();
                    } else if (value == com.fasterxml.jackson.core.JsonToken.VALUE_NULL) {
                        m[member] = null;
                    } else {
                        return null;
                    }
                } else {
                    p.skipChildren(); // an unknown member: ignored, as the general path does
                }
            }
            if (t != com.fasterxml.jackson.core.JsonToken.END_OBJECT || p.nextToken() != null || v != VERSION || !typed
                    || m[0] == null || m[1] == null || m[4] == null || m[5] == null) {
                return null;
            }
            Optional<AgentKind> kind = Optional.empty();
            if (m[3] != null) {
                kind = java.util.Arrays.stream(AgentKind.values()).filter(k -> k.name().equalsIgnoreCase(m[3])).findFirst();
                if (kind.isEmpty()) {
                    return null;
                }
            }
            if (Optional.ofNullable(m[2]).isPresent() == kind.isPresent()) {
                return null;
            }
            return new Message.Relay(m[0], m[1], Optional.ofNullable(m[2]), kind, m[4], m[5]);
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** The members of a relay, in the order {@link #plainRelay} keeps them. */
    private static final java.util.List<String> RELAY_MEMBERS =
            java.util.List.of("id", "from", "toAgent", "toKind", "subject", "body");

    /** A {@code relay} read member by member, with the same checks data binding makes. */
    private static Message.Relay relay(ObjectNode b) {
        try {
            return new Message.Relay(text(b, "id"), text(b, "from"), optionalText(b, "toAgent"),
                    optionalText(b, "toKind").map(MessageCodec::kind),
                    text(b, "subject"), text(b, "body"));
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(ErrorCode.BAD_MESSAGE, "Bad 'relay' message: " + e.getMessage(), e);
        }
    }

    private static AgentKind kind(String k) {
        return java.util.Arrays.stream(AgentKind.values()).filter(a -> a.name().equalsIgnoreCase(k)).findFirst()
                .orElseThrow(() -> new ProtocolException(ErrorCode.BAD_MESSAGE, "Bad 'relay' message: the member "
                        + "'toKind' must be robot, user, service or peer, not '" + k + "'."));
    }

    private static String text(ObjectNode b, String name) {
        JsonNode n = b.get(name);
        if (!n.isTextual()) {
            throw new ProtocolException(ErrorCode.BAD_MESSAGE, "Bad 'relay' message: the member '" + name
                    + "' must be a string, not " + n.getNodeType().name().toLowerCase(java.util.Locale.ROOT) + ".");
        }
        return n.textValue();
    }

    private static Optional<String> optionalText(ObjectNode b, String name) {
        JsonNode n = b.get(name);
        return n == null || n.isNull() ? Optional.empty() : Optional.of(text(b, name));
    }

    private static String rootMessage(Throwable e) {
        Throwable t = e;
        while (t.getCause() != null && t.getCause() != t) {
            t = t.getCause();
        }
        String m = t instanceof JacksonException j ? j.getOriginalMessage() : t.getMessage();
        if (t instanceof NullPointerException) {
            // A record's check of a member, or a null in an object of strings (a binding, an argument).
            return m == null ? "a value is null where the protocol wants one." : "'" + m + "' is null.";
        }
        return m == null ? t.getClass().getSimpleName() : m;
    }
}
