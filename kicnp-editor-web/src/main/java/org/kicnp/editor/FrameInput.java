package org.kicnp.editor;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.BiFunction;
import org.kicnp.core.ConditionParser;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameKind;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.Provenance;
import org.kicnp.core.Relation;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * Reads a frame from the JSON the page sends (the shape of {@link FrameViews.Detail}, read leniently) and checks
 * everything that needs no other frame: names, kinds, data types, values against their types, condition syntax,
 * value and default both given. Every problem is collected, naming frame and slot, so the page can show them all
 * at once; only a frame without any problem is returned. The one thing read from other frames: a slot sent without a
 * type takes the type its frame's ancestors declare for that slot, as a slot without TYPE does in the XML (a slot
 * none of them declares is a string).
 */
final class FrameInput {
    private final JsonNode json;
    private final String frameName;
    /** The type that frame {@code parent} (or a frame above it) declares for a slot, if any: (parent, slot). */
    private final BiFunction<String, String, Optional<DataType>> declaredType;
    /** The nearest ARGUMENT that frame {@code parent} or a frame above it gives a slot, if any: (parent, slot). */
    private final BiFunction<String, String, Optional<String>> declaredArgument;
    private Optional<String> parent = Optional.empty();
    private final List<ApiProblem> problems = new ArrayList<>();

    private FrameInput(JsonNode json, String frameName,
            BiFunction<String, String, Optional<DataType>> declaredType,
            BiFunction<String, String, Optional<String>> declaredArgument) {
        this.declaredType = declaredType;
        this.declaredArgument = declaredArgument;
        this.json = json;
        this.frameName = frameName;
    }

    /**
     * The frame as read, and the problems found reading it. With problems, {@code frame} (when there is one) is the
     * frame without the items that had them, so that the frame model can still be asked about the rest.
     */
    record Read(Optional<Frame> frame, List<ApiProblem> problems) {
    }

    /**
     * Reads the frame; {@code name} is the frame name from the URL, or empty to take it from the body.
     *
     * @throws ApiException 400 when the body is not a JSON object
     */
    static Read read(JsonNode json, Optional<String> name,
            BiFunction<String, String, Optional<DataType>> declaredType,
            BiFunction<String, String, Optional<String>> declaredArgument) {
        if (json == null || !json.isObject()) {
            throw new ApiException(400, "The request body must be a JSON object describing a frame.");
        }
        String n = name.orElseGet(() -> text(json, "name").orElse(""));
        FrameInput in = new FrameInput(json, n, declaredType, declaredArgument);
        Frame frame = in.build();
        return new Read(Optional.ofNullable(frame), List.copyOf(in.problems));
    }

    private Frame build() {
        if (frameName.isBlank()) {
            problems.add(ApiProblem.of("", "", "A frame needs a name."));
            return null;
        }
        Optional<String> bodyName = text(json, "name");
        if (bodyName.isPresent() && !bodyName.get().equals(frameName)) {
            problems.add(ApiProblem.of(frameName, "", "The body names frame '" + bodyName.get() + "' but the address "
                    + "names '" + frameName + "'; use rename to change a frame's name."));
        }
        FrameKind kind = FrameKind.CLASS;
        String kindText = field(json, "kind", "").orElse("CLASS").toUpperCase(Locale.ROOT);
        switch (kindText) {
            case "CLASS" -> kind = FrameKind.CLASS;
            case "INSTANCE" -> kind = FrameKind.INSTANCE;
            default -> problems.add(ApiProblem.of(frameName, "", "Frame '" + frameName + "' has kind '" + kindText
                    + "'; it must be CLASS or INSTANCE."));
        }
        Frame.Builder b = Frame.builder(frameName, kind);
        parent = field(json, "parent", "");
        parent.ifPresent(b::parent);
        field(json, "provenance", "").ifPresent(p -> provenance(p).ifPresent(b::provenance));
        if (json.hasNonNull("priority")) {
            priority(json.get("priority")).ifPresent(b::priority);
        }
        strings(json, "parts", "").forEach(b::part);
        for (JsonNode l : array(json, "linksTo", "")) {
            link(l).ifPresent(sl -> b.linkTo(Relation.parse(sl[0]), sl[1]));
        }
        for (JsonNode l : array(json, "linksFrom", "")) {
            link(l).ifPresent(sl -> b.linkFrom(Relation.parse(sl[0]), sl[1]));
        }
        List<String> seen = new ArrayList<>();
        for (JsonNode s : array(json, "slots", "")) {
            slot(s).ifPresent(slot -> {
                if (seen.contains(slot.name())) {
                    problems.add(ApiProblem.of(frameName, slot.name(), "Frame '" + frameName + "' has two slots named '"
                            + slot.name() + "'."));
                } else {
                    seen.add(slot.name());
                    b.slot(slot);
                }
            });
        }
        try {
            return b.build();
        } catch (KnowledgeException e) {
            problems.add(ApiProblem.of(frameName, "", e.getMessage()));
            return null;
        }
    }

    /** An integer, as a JSON number or text; anything else is a problem, never a silent 0 or a clipped value. */
    private Optional<Integer> priority(JsonNode p) {
        if (p.isIntegralNumber() && p.canConvertToInt()) {
            return Optional.of(p.intValue());
        }
        if (p.isTextual()) {
            try {
                return Optional.of(Integer.parseInt(p.asText().strip()));
            } catch (NumberFormatException e) {
                // reported below
            }
        }
        problems.add(ApiProblem.of(frameName, "", "Frame '" + frameName + "' has priority " + p
                + ", which is not an integer (from " + Integer.MIN_VALUE + " to " + Integer.MAX_VALUE + ")."));
        return Optional.empty();
    }

    private Optional<Provenance> provenance(String p) {
        try {
            return Optional.of(Provenance.valueOf(p.toUpperCase(Locale.ROOT)));
        } catch (IllegalArgumentException e) {
            problems.add(ApiProblem.of(frameName, "", "Frame '" + frameName + "' has provenance '" + p
                    + "'; it must be DECLARED, LEARNED or RUNTIME."));
            return Optional.empty();
        }
    }

    private Optional<String[]> link(JsonNode l) {
        Optional<String> relation = text(l, "relation");
        Optional<String> frame = text(l, "frame");
        if (relation.isEmpty() || frame.isEmpty()) {
            problems.add(ApiProblem.of(frameName, "", "A semantic link of frame '" + frameName
                    + "' needs both a relation and a frame."));
            return Optional.empty();
        }
        return Optional.of(new String[] {relation.get(), frame.get()});
    }

    private Optional<Slot> slot(JsonNode s) {
        String name = text(s, "name").orElse("");
        String where = "Slot '" + name + "' of frame '" + frameName + "'";
        if (name.isBlank()) {
            problems.add(ApiProblem.of(frameName, "", "A slot of frame '" + frameName + "' has no name."));
            return Optional.empty();
        }
        String typeText = field(s, "type", name).orElseGet(() -> parent.flatMap(p -> declaredType.apply(p, name))
                .map(DataType::xmlName).orElse("TYPE_STR"));
        Optional<DataType> type = DataType.parse(typeText);
        if (type.isEmpty()) {
            problems.add(ApiProblem.of(frameName, name, where + " has the unknown data type '" + typeText + "'."));
            return Optional.empty();
        }
        int before = problems.size();
        Slot.Builder b = Slot.builder(name, type.get());
        field(s, "role", name).ifPresent(b::role);
        field(s, "from", name).ifPresent(b::from);
        field(s, "argument", name).ifPresent(b::argument);
        field(s, "frameRelated", name).ifPresent(b::frameRelated);
        b.frameListRelated(strings(s, "frameListRelated", name));
        field(s, "onNeeded", name).ifPresent(b::onNeeded);
        field(s, "onAdded", name).ifPresent(b::onAdded);
        field(s, "onRemoved", name).ifPresent(b::onRemoved);
        b.required(flag(s, "required", false, where)).shared(flag(s, "shared", true, where))
                .unique(flag(s, "unique", false, where)).reactive(flag(s, "reactive", true, where));
        field(s, "condition", name).ifPresent(c -> {
            try {
                b.condition(ConditionParser.parse(c));
            } catch (KnowledgeException e) {
                problems.add(ApiProblem.of(frameName, name, where + ": " + e.getMessage()));
            }
        });
        Optional<String> argument = text(s, "argument");
        if (type.get() == DataType.LIST && argument.isEmpty()) {
            // The items take the nearest ARGUMENT above, as the XML loader and the knowledge base's declarations do.
            argument = parent.flatMap(p -> declaredArgument.apply(p, name));
        }
        value(s.get("value"), type.get(), argument, name, where + " value").ifPresent(b::value);
        value(s.get("defaultValue"), type.get(), argument, name, where + " default").ifPresent(b::defaultValue);
        if (problems.size() > before) {
            return Optional.empty();
        }
        try {
            return Optional.of(b.build());
        } catch (KnowledgeException e) {
            problems.add(ApiProblem.of(frameName, name, "In frame '" + frameName + "': " + e.getMessage()));
            return Optional.empty();
        }
    }

    /** A value as text (a scalar) or an array of texts (a list); empty text and null mean "no value". */
    private Optional<Value> value(JsonNode v, DataType type, Optional<String> argument, String slot, String what) {
        if (v == null || v.isNull() || v.isTextual() && v.asText().isEmpty()) {
            return Optional.empty();
        }
        try {
            if (type == DataType.LIST) {
                DataType item = argument.flatMap(DataType::parse).orElse(argument.isPresent() ? DataType.INSTANCE
                        : DataType.STRING);
                List<Value> items = new ArrayList<>();
                if (v.isArray()) {
                    for (JsonNode i : v) {
                        if (!i.isValueNode()) {
                            throw new IllegalArgumentException("the item " + abbreviate(i.toString())
                                    + " is not a text; lists inside lists are not supported.");
                        }
                        items.add(Value.parse(item, i.asText()));
                    }
                } else if (!v.isValueNode()) {
                    throw new IllegalArgumentException(abbreviate(v.toString()) + " is not a list: write an array of "
                            + "texts or comma-separated text.");
                } else {
                    for (String part : v.asText().split(",")) {
                        if (!part.isBlank()) {
                            items.add(Value.parse(item, part.strip()));
                        }
                    }
                }
                return Optional.of(new Value.Lst(items));
            }
            if (!v.isValueNode()) {
                throw new IllegalArgumentException("A " + type.xmlName() + " value must be written as text.");
            }
            return Optional.of(Value.parse(type, v.asText()));
        } catch (IllegalArgumentException e) {
            problems.add(ApiProblem.of(frameName, slot, what + " is not valid: " + e.getMessage()));
            return Optional.empty();
        }
    }

    /**
     * A facet flag: a JSON boolean, or text the XML format accepts ({@code TRUE}, {@code no}, {@code 1}…). Anything
     * else is a problem: reading it as the default would save a facet the person did not ask for.
     */
    private boolean flag(JsonNode s, String field, boolean otherwise, String where) {
        JsonNode f = s.get(field);
        if (f == null || f.isNull()) {
            return otherwise;
        }
        if (f.isBoolean()) {
            return f.booleanValue();
        }
        if (f.isValueNode()) {
            try {
                return ((Value.Bool) Value.parse(DataType.BOOLEAN, f.asText())).value();
            } catch (IllegalArgumentException e) {
                // reported below
            }
        }
        problems.add(ApiProblem.of(frameName, text(s, "name").orElse(""), where + " has " + field + " " + f
                + ", which is not true or false."));
        return otherwise;
    }

    /**
     * A text item of the frame (slot empty) or of a slot, as {@link #text}; an object or array there is a problem, not
     * an absent item: taking it as absent would make a frame a root or a slot a string without a word.
     */
    private Optional<String> field(JsonNode node, String field, String slot) {
        JsonNode f = node.get(field);
        if (f != null && !f.isNull() && !f.isValueNode()) {
            String of = owner(slot);
            problems.add(ApiProblem.of(frameName, slot, of + " has " + field + " " + abbreviate(f.toString())
                    + ", which is not a text."));
            return Optional.empty();
        }
        return text(node, field);
    }

    static Optional<String> text(JsonNode node, String field) {
        JsonNode f = node == null ? null : node.get(field);
        if (f == null || f.isNull() || !f.isValueNode()) {
            return Optional.empty();
        }
        String t = f.asText();
        return t.isBlank() ? Optional.empty() : Optional.of(t);
    }

    /**
     * The array in {@code field}, empty when the field is absent or null. Any other JSON is a problem: taking it as
     * empty would make a save drop every slot (or part, or link) the frame had.
     */
    private Iterable<JsonNode> array(JsonNode node, String field, String slot) {
        JsonNode f = node.get(field);
        if (f == null || f.isNull()) {
            return List.of();
        }
        if (!f.isArray()) {
            String of = owner(slot);
            problems.add(ApiProblem.of(frameName, slot, of + " has " + field + " " + abbreviate(f.toString())
                    + ", which is not an array."));
            return List.of();
        }
        return f;
    }

    /** How a message names what an item belongs to: the frame (slot empty) or one of its slots. */
    private String owner(String slot) {
        return slot.isEmpty() ? "Frame '" + frameName + "'" : "Slot '" + slot + "' of frame '" + frameName + "'";
    }

    private static String abbreviate(String t) {
        return t.length() <= 40 ? t : t.substring(0, 37) + "...";
    }

    private List<String> strings(JsonNode node, String field, String slot) {
        List<String> out = new ArrayList<>();
        for (JsonNode i : array(node, field, slot)) {
            if (!i.asText().isBlank()) {
                out.add(i.asText().strip());
            }
        }
        return out;
    }
}
