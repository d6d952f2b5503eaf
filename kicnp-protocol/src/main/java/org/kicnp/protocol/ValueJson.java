package org.kicnp.protocol;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.databind.DeserializationContext;
import com.fasterxml.jackson.databind.JsonDeserializer;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.JsonSerializer;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializerProvider;
import com.fasterxml.jackson.databind.module.SimpleModule;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.kicnp.core.Value;

/**
 * Maps slot {@link Value}s to plain JSON values and back: string, integer, number with a fraction, boolean, array,
 * {@code {"ref": "frame"}} for a frame reference, and {@code {"float": "NaN"}} (or {@code "Infinity"},
 * {@code "-Infinity"}) for a float JSON has no number for (a script's 0/0, say), so that it arrives a float, not the
 * text "NaN". Kept here so the core domain carries no Jackson annotations.
 */
public final class ValueJson {
    /** The texts of {@code {"float": …}}: the floats JSON has no number for. */
    static final String NAN = "NaN";
    static final String INFINITY = "Infinity";
    static final String MINUS_INFINITY = "-Infinity";

    private ValueJson() {
    }

    /**
     * A slot value from its JSON form, as the protocol reads it (text, whole number, number, boolean, array, or
     * {@code {"ref": "frame"}}); {@code refuse} makes the exception thrown for the first node, at any depth, that is
     * none of these.
     */
    public static Value fromJson(JsonNode node, java.util.function.Function<JsonNode, ? extends RuntimeException> refuse) {
        if (node.isTextual()) {
            return Value.of(node.textValue());
        }
        if (node.isIntegralNumber() && node.canConvertToLong()) {
            return Value.of(node.longValue());
        }
        if (node.isNumber()) {
            return Value.of(node.doubleValue());
        }
        if (node.isBoolean()) {
            return Value.of(node.booleanValue());
        }
        if (node.isArray()) {
            List<Value> items = new ArrayList<>(node.size());
            for (JsonNode item : node) {
                items.add(fromJson(item, refuse));
            }
            return new Value.Lst(items);
        }
        if (node.isObject() && node.size() == 1 && node.path("ref").isTextual()) {
            return Value.ref(node.get("ref").textValue());
        }
        if (node.isObject() && node.size() == 1 && node.path("float").isTextual()) {
            Double special = switch (node.get("float").textValue()) {
                case NAN -> Double.NaN;
                case INFINITY -> Double.POSITIVE_INFINITY;
                case MINUS_INFINITY -> Double.NEGATIVE_INFINITY;
                default -> null; // not one of the three: refused below
            };
            if (special != null) {
                return Value.of(special);
            }
        }
        throw refuse.apply(node);
    }

    /** A slot value in its JSON form, as the protocol writes it (the inverse of {@link #fromJson}). */
    public static JsonNode toJson(Value v) {
        return TREES.valueToTree(v);
    }

    /** Only for {@link #toJson}: the same writer as the protocol's messages use. */
    private static final ObjectMapper TREES = new ObjectMapper().registerModule(module());

    static SimpleModule module() {
        SimpleModule m = new SimpleModule("kicnp-values");
        m.addSerializer(Value.class, new Writer());
        m.addDeserializer(Value.class, new Reader());
        return m;
    }

    private static final class Writer extends JsonSerializer<Value> {
        @Override public void serialize(Value v, JsonGenerator g, SerializerProvider p) throws IOException {
            switch (v) {
                case Value.Str s -> g.writeString(s.value());
                case Value.Int i -> g.writeNumber(i.value());
                case Value.Real r when Double.isFinite(r.value()) -> g.writeNumber(r.value());
                case Value.Real r -> {
                    g.writeStartObject();
                    g.writeStringField("float", Double.isNaN(r.value()) ? NAN
                            : r.value() > 0 ? INFINITY : MINUS_INFINITY);
                    g.writeEndObject();
                }
                case Value.Bool b -> g.writeBoolean(b.value());
                case Value.Ref r -> {
                    g.writeStartObject();
                    g.writeStringField("ref", r.frame());
                    g.writeEndObject();
                }
                case Value.Lst l -> {
                    g.writeStartArray();
                    for (Value item : l.items()) {
                        serialize(item, g, p);
                    }
                    g.writeEndArray();
                }
            }
        }

        @Override public Class<Value> handledType() {
            return Value.class;
        }
    }

    private static final class Reader extends JsonDeserializer<Value> {
        @Override public Value deserialize(JsonParser parser, DeserializationContext ctx) throws IOException {
            JsonNode node = ctx.readTree(parser);
            return toValue(node, parser);
        }

        private static Value toValue(JsonNode node, JsonParser parser) throws IOException {
            try {
                return fromJson(node, NotAValue::new);
            } catch (NotAValue e) {
                throw new com.fasterxml.jackson.databind.exc.InvalidFormatException(parser,
                        "A slot value must be a string, a number, a boolean, an array, {\"ref\": \"frame\"} or "
                                + "{\"float\": \"NaN\"} (or \"Infinity\", \"-Infinity\"), not " + e.node + ".", node,
                        Value.class);
            }
        }

        /** The node {@link #fromJson} found no slot value in, carried out to be reported at the parser. */
        private static final class NotAValue extends RuntimeException {
            final transient JsonNode node;

            NotAValue(JsonNode node) {
                super(null, null, false, false);
                this.node = node;
            }
        }
    }
}
