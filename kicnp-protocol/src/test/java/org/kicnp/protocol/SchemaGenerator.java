package org.kicnp.protocol;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.kicnp.core.Value;

/**
 * Derives the published JSON Schema (draft 2020-12) of each message type from its record, so the schemas in
 * {@code docs/protocol/schemas} cannot drift from the code: {@link SchemasTest} compares them.
 */
final class SchemaGenerator {
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private SchemaGenerator() {
    }


    static ObjectNode schema(MessageType type) {
        ObjectNode s = JSON.createObjectNode();
        s.put("$schema", "https://json-schema.org/draft/2020-12/schema");
        s.put("$id", "https://kicnp.org/protocol/v1/" + type.wireName() + ".json");
        s.put("title", "K-ICNP '" + type.wireName() + "' message (protocol version 1)");
        s.put("type", "object");
        ObjectNode props = s.putObject("properties");
        props.putObject("v").put("const", MessageCodec.VERSION);
        props.putObject("type").put("const", type.wireName());
        ArrayNode required = JSON.createArrayNode().add("v").add("type");
        components(type.recordClass(), props, required);
        s.set("required", required);
        if (type == MessageType.RELAY) {
            ArrayNode exactlyOne = s.putArray("oneOf");
            exactlyOne.addObject().putArray("required").add("toAgent");
            exactlyOne.addObject().putArray("required").add("toKind");
        }
        if (type == MessageType.SENSOR) {
            ((ObjectNode) props.get("ttlMs")).put("minimum", 1).put("maximum", Message.SensorSignal.MAX_TTL_MS);
        }
        limitedMembers(type).forEach(m -> ((ObjectNode) props.get(m)).put("maxLength", Message.MAX_NAME_LENGTH));
        return s;
    }

    /**
     * The string members the record of {@code type} holds to {@link Message#MAX_NAME_LENGTH}: found by building the
     * {@link Samples} message of that type again with each one a character longer than that, so the schemas say what
     * the records (and so the gateway, which decodes into them) refuse, and no table can drift from them.
     */
    private static List<String> limitedMembers(MessageType type) {
        Message sample = Samples.all().stream().filter(type.recordClass()::isInstance).findFirst().orElseThrow();
        RecordComponent[] parts = type.recordClass().getRecordComponents();
        String tooLong = "n".repeat(Message.MAX_NAME_LENGTH + 1);
        List<String> limited = new ArrayList<>();
        for (int k = 0; k < parts.length; k++) {
            Object[] args = new Object[parts.length];
            for (int j = 0; j < parts.length; j++) {
                args[j] = value(parts[j], sample);
            }
            if (parts[k].getType() == String.class) {
                args[k] = tooLong;
            } else if (parts[k].getGenericType() instanceof ParameterizedType p && p.getRawType() == Optional.class
                    && p.getActualTypeArguments()[0] == String.class) {
                args[k] = Optional.of(tooLong);
            } else {
                continue;
            }
            if (refusedAsTooLong(type.recordClass(), parts, args, parts[k].getName())) {
                limited.add(parts[k].getName());
            }
        }
        return limited;
    }

    private static Object value(RecordComponent part, Message sample) {
        try {
            return part.getAccessor().invoke(sample);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("Cannot read '" + part.getName() + "' of " + sample + ".", e);
        }
    }

    private static boolean refusedAsTooLong(Class<?> record, RecordComponent[] parts, Object[] args, String member) {
        try {
            record.getDeclaredConstructor(Arrays.stream(parts).map(RecordComponent::getType).toArray(Class<?>[]::new))
                    .newInstance(args);
            return false;
        } catch (InvocationTargetException e) {
            return e.getCause() instanceof IllegalArgumentException i && i.getMessage().equals("The member '" + member
                    + "' is " + (Message.MAX_NAME_LENGTH + 1) + " characters long; at most " + Message.MAX_NAME_LENGTH
                    + " are allowed.");
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("Cannot build a " + record.getSimpleName() + ".", e);
        }
    }

    private static ObjectNode typeSchema(Type t) {
        ObjectNode n = JSON.createObjectNode();
        if (t instanceof ParameterizedType p) {
            Class<?> raw = (Class<?>) p.getRawType();
            Type[] args = p.getActualTypeArguments();
            if (raw == List.class) {
                n.put("type", "array");
                n.set("items", typeSchema(args[0]));
            } else if (raw == java.util.Map.class) {
                n.put("type", "object");
                n.set("additionalProperties", typeSchema(args[1]));
            } else {
                throw new IllegalStateException("No schema for " + t);
            }
            return n;
        }
        Class<?> c = (Class<?>) t;
        if (c == String.class) {
            n.put("type", "string");
        } else if (c == long.class || c == int.class || c == Long.class) {
            n.put("type", "integer");
        } else if (c == double.class || c == Double.class) {
            n.put("type", "number");
        } else if (c == boolean.class) {
            n.put("type", "boolean");
        } else if (c.isEnum()) {
            n.put("type", "string");
            ArrayNode values = n.putArray("enum");
            Arrays.stream(c.getEnumConstants()).forEach(e -> values.add(e.toString().toLowerCase(Locale.ROOT)));
        } else if (c == Value.class) {
            n.put("$ref", "#/$defs/value");
        } else if (NESTED.contains(c)) {
            n.put("$ref", "#/$defs/" + defName(c));
        } else {
            throw new IllegalStateException("No schema for " + c);
        }
        return n;
    }

    /** The records that are parts of messages, not messages: each defined once under {@code $defs}. */
    private static final List<Class<?>> NESTED = List.of(Message.ProofNode.class,
            Message.Reason.class, Message.SlotCandidates.class, Message.BindingOutcome.class);

    private static String defName(Class<?> c) {
        return Character.toLowerCase(c.getSimpleName().charAt(0)) + c.getSimpleName().substring(1);
    }

    /** The schema of a record that is part of a message: its components, those not optional required. */
    private static ObjectNode recordSchema(Class<?> c) {
        ObjectNode s = JSON.createObjectNode();
        s.put("type", "object");
        ArrayNode required = JSON.createArrayNode();
        components(c, s.putObject("properties"), required);
        s.set("required", required);
        return s;
    }

    /** A record's components as schema properties; those that are not optional are also required. */
    private static void components(Class<?> record, ObjectNode props, ArrayNode required) {
        for (RecordComponent rc : record.getRecordComponents()) {
            Type t = rc.getGenericType();
            if (rc.getType() == Optional.class) {
                t = ((ParameterizedType) t).getActualTypeArguments()[0];
            } else {
                required.add(rc.getName());
            }
            props.set(rc.getName(), typeSchema(t));
        }
    }

    /** Adds the definitions of a slot value and of the records a schema refers to. */
    static ObjectNode withDefinitions(ObjectNode schema) {
        for (Class<?> c : NESTED) {
            if (schema.toString().contains("#/$defs/" + defName(c))) {
                ObjectNode defs = schema.has("$defs") ? (ObjectNode) schema.get("$defs") : schema.putObject("$defs");
                defs.set(defName(c), recordSchema(c));
            }
        }
        if (!schema.toString().contains("#/$defs/value")) {
            return schema;
        }
        ObjectNode defs = schema.has("$defs") ? (ObjectNode) schema.get("$defs") : schema.putObject("$defs");
        ObjectNode value = defs.putObject("value");
        ArrayNode any = value.putArray("oneOf");
        any.addObject().put("type", "string");
        any.addObject().put("type", "number");
        any.addObject().put("type", "boolean");
        any.addObject().put("type", "array").putObject("items").put("$ref", "#/$defs/value");
        ObjectNode ref = any.addObject();
        ref.put("type", "object");
        ref.putObject("properties").putObject("ref").put("type", "string");
        ref.putArray("required").add("ref");
        ref.put("additionalProperties", false);
        ObjectNode nonFinite = any.addObject();
        nonFinite.put("type", "object");
        nonFinite.putObject("properties").putObject("float").putArray("enum").add(ValueJson.NAN)
                .add(ValueJson.INFINITY).add(ValueJson.MINUS_INFINITY);
        nonFinite.putArray("required").add("float");
        nonFinite.put("additionalProperties", false);
        return schema;
    }
}
