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
            .serializationInclusion(JsonInclude.Include.NON_ABSENT)
            .build();

    /** Encodes a message as the UTF-8 JSON payload of one frame, envelope first. */
    public byte[] encode(Message message) {
        ObjectNode node = mapper.createObjectNode();
        node.put("v", VERSION);
        node.put("type", MessageType.of(message).wireName());
        node.setAll((ObjectNode) mapper.valueToTree(message));
        try {
            return mapper.writeValueAsBytes(node);
        } catch (JacksonException e) {
            throw new IllegalStateException("Could not encode a '" + MessageType.of(message).wireName() + "' message.", e);
        }
    }

    /**
     * Decodes the payload of one frame.
     *
     * @throws ProtocolException with {@link ErrorCode#BAD_JSON}, {@link ErrorCode#UNSUPPORTED_VERSION},
     *     {@link ErrorCode#UNKNOWN_TYPE} or {@link ErrorCode#BAD_MESSAGE}, and a sentence saying what is wrong
     */
    public Message decode(byte[] payload) {
        JsonNode root = readTree(payload);
        JsonNode v = root.get("v");
        if (v == null || !v.isIntegralNumber() || v.asLong() != VERSION) {
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
        try {
            return mapper.treeToValue(body, type.recordClass());
        } catch (JacksonException | IllegalArgumentException e) {
            throw new ProtocolException(ErrorCode.BAD_MESSAGE,
                    "Bad '" + typeName + "' message: " + rootMessage(e), e);
        }
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
        for (RecordComponent c : type.recordClass().getRecordComponents()) {
            JsonNode member = body.get(c.getName());
            if (c.getType() != Optional.class && (member == null || member.isNull())) {
                throw new ProtocolException(ErrorCode.BAD_MESSAGE,
                        "A '" + type.wireName() + "' message needs the member '" + c.getName() + "'.");
            }
        }
    }

    private static String rootMessage(Throwable e) {
        Throwable t = e;
        while (t.getCause() != null && t.getCause() != t) {
            t = t.getCause();
        }
        String m = t instanceof JacksonException j ? j.getOriginalMessage() : t.getMessage();
        return m == null ? t.getClass().getSimpleName() : m;
    }
}
