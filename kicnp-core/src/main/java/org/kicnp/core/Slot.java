package org.kicnp.core;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * A slot with every facet of the paper's Table 2, plus FRL-style demons ({@code onNeeded}, {@code onAdded},
 * {@code onRemoved}) and a reactive flag. Immutable; build one with {@link #builder(String, DataType)} and change
 * one with {@link #toBuilder()}. A slot may hold a value or a default, never both.
 */
public final class Slot {
    private static final int REQUIRED = 1;
    private static final int SHARED = 2;
    private static final int UNIQUE = 4;
    private static final int REACTIVE = 8;

    private final String name;
    private final Value value;
    /** Everything but the name and the value: shared by the slots made from one another ({@link #withValue}). */
    private final Facets facets;

    /**
     * A slot's facets besides its name and value. A slot filled from another ({@link #withValue}: an engine fills its
     * rules' slots at every firing) shares them, and so do all plain slots of one type (a value and nothing else, as
     * sensors' and engines' instances hold them): a slot is then three references, not twelve fields.
     */
    private record Facets(DataType type, int flags, Value defaultValue, Condition condition, String argument,
            String role, String from, String frameRelated, List<String> frameListRelated, Demons demons) {
        private static final Facets[] PLAIN = plain();

        private static Facets[] plain() {
            Facets[] out = new Facets[DataType.values().length];
            for (DataType t : DataType.values()) {
                out[t.ordinal()] = new Facets(t, SHARED | REACTIVE, null, Condition.ANY, null, null, null, null,
                        List.of(), null);
            }
            return out;
        }

        /** These facets, or the shared plain facets of the type when they are those. */
        static Facets of(DataType type, int flags, Value defaultValue, Condition condition, String argument,
                String role, String from, String frameRelated, List<String> frameListRelated, Demons demons) {
            if (flags == (SHARED | REACTIVE) && defaultValue == null && condition instanceof Condition.Any
                    && argument == null && role == null && from == null && frameRelated == null
                    && frameListRelated.isEmpty() && demons == null) {
                return PLAIN[type.ordinal()];
            }
            return new Facets(type, flags, defaultValue, condition, argument, role, from, frameRelated,
                    frameListRelated, demons);
        }
    }

    private Slot(Builder b) {
        this.name = Names.canonical(b.name); // few slot names, many slots: one String each, compared fast
        this.value = b.value;
        this.facets = Facets.of(b.type, b.flags, b.defaultValue, b.condition, b.argument, b.role, b.from,
                b.frameRelated, b.frameListRelated, b.demons);
    }

    /** This slot with {@code value} in place of its own: same name, type and facets (a copy, not a builder). */
    private Slot(Slot s, Value value) {
        this.name = s.name;
        this.value = value;
        this.facets = s.facets;
    }

    /** Starts a slot with the paper's defaults: not required, shared, not unique, reactive, condition ANY. */
    public static Builder builder(String name, DataType type) {
        return new Builder(name, type);
    }

    /** A slot that only carries a value, as instance frames usually hold them. */
    public static Slot ofValue(String name, DataType type, Value value) {
        return builder(name, type).value(value).build();
    }

    public Builder toBuilder() {
        return new Builder(this);
    }

    /**
     * This slot holding {@code value}, everything else the same: what {@code toBuilder().value(value).build()} makes,
     * with the same checks, without a builder (an inference engine fills a rule's slots this way at every firing).
     *
     * @throws InvalidFrameException when the slot has a default, or the value does not fit the type
     */
    public Slot withValue(Value value) {
        requireNonNull(value, "value");
        if (facets.defaultValue != null) {
            throw bothValueAndDefault(name);
        }
        checkFits(name, facets.type, value, "value");
        return new Slot(this, value);
    }

    private static InvalidFrameException bothValueAndDefault(String name) {
        return new InvalidFrameException("Slot '" + name + "' has both a value and a default; "
                + "the paper allows one or the other (Table 2).");
    }

    private static void checkFits(String name, DataType type, Value v, String what) {
        if (v == null) {
            return;
        }
        boolean fits = switch (type) {
            case INSTANCE, FRAME -> v instanceof Value.Ref;
            case STRING -> v instanceof Value.Str;
            case INTEGER -> v instanceof Value.Int;
            case FLOAT -> v instanceof Value.Real || v instanceof Value.Int;
            case BOOLEAN -> v instanceof Value.Bool;
            case LIST -> v instanceof Value.Lst;
        };
        if (!fits) {
            throw new InvalidFrameException("The " + what + " '" + v.text() + "' of slot '" + name
                    + "' is not of its type " + type.xmlName() + ".");
        }
    }

    public String name() {
        return name;
    }

    public DataType type() {
        return facets.type;
    }

    public Optional<Value> value() {
        return Optional.ofNullable(value);
    }

    public Optional<Value> defaultValue() {
        return Optional.ofNullable(facets.defaultValue);
    }

    /** The value if there is one, else the default. */
    public Optional<Value> effectiveValue() {
        return Optional.ofNullable(effectiveValueOrNull());
    }

    /**
     * {@link #effectiveValue()}, or null when there is neither: for readers of slot values on a hot path (an inference
     * engine's matching reads one per fact and index), where an Optional per read is measurable garbage.
     */
    public Value effectiveValueOrNull() {
        return value != null ? value : facets.defaultValue;
    }

    public Condition condition() {
        return facets.condition;
    }

    /** For an instance slot, the class its value must be an instance of; for a list, the item type or class. */
    public Optional<String> argument() {
        return Optional.ofNullable(facets.argument);
    }

    public Optional<String> role() {
        return Optional.ofNullable(facets.role);
    }

    /** Table 2's "from": the source of the slot's value (a sensor, an agent, a frame). */
    public Optional<String> from() {
        return Optional.ofNullable(facets.from);
    }

    public Optional<String> frameRelated() {
        return Optional.ofNullable(facets.frameRelated);
    }

    public List<String> frameListRelated() {
        return facets.frameListRelated;
    }

    public boolean required() {
        return (facets.flags & REQUIRED) != 0;
    }

    public boolean shared() {
        return (facets.flags & SHARED) != 0;
    }

    public boolean unique() {
        return (facets.flags & UNIQUE) != 0;
    }

    /** Whether writes to this slot re-trigger matching; demons write to non-reactive slots to avoid loops. */
    public boolean reactive() {
        return (facets.flags & REACTIVE) != 0;
    }

    // Null-returning twins of the accessors above, for the knowledge base's hot paths (validation, indexing,
    // inheritance), where an Optional per call is measurable garbage.

    Value valueOrNull() {
        return value;
    }

    Value defaultOrNull() {
        return facets.defaultValue;
    }

    String argumentOrNull() {
        return facets.argument;
    }

    String frameRelatedOrNull() {
        return facets.frameRelated;
    }

    public Optional<String> onNeeded() {
        return Optional.ofNullable(facets.demons == null ? null : facets.demons.onNeeded);
    }

    public Optional<String> onAdded() {
        return Optional.ofNullable(facets.demons == null ? null : facets.demons.onAdded);
    }

    public Optional<String> onRemoved() {
        return Optional.ofNullable(facets.demons == null ? null : facets.demons.onRemoved);
    }

    @Override public boolean equals(Object o) {
        return o instanceof Slot s && name.equals(s.name) && Objects.equals(value, s.value)
                && (facets == s.facets || facets.equals(s.facets));
    }

    @Override public int hashCode() {
        return Objects.hash(name, facets.type, facets.flags, value, facets.defaultValue, facets.condition,
                facets.argument);
    }

    @Override public String toString() {
        return "Slot[" + name + ": " + facets.type.xmlName() + (value != null ? " = " + value.text() : "")
                + (facets.defaultValue != null ? " default " + facets.defaultValue.text() : "") + "]";
    }

    private record Demons(String onNeeded, String onAdded, String onRemoved) {
    }

    /** Builds a {@link Slot}. Facet checks that need no other frame happen in {@link #build()}. */
    public static final class Builder {
        private final String name;
        private DataType type;
        private int flags = SHARED | REACTIVE;
        private Value value;
        private Value defaultValue;
        private Condition condition = Condition.ANY;
        private String argument;
        private String role;
        private String from;
        private String frameRelated;
        private List<String> frameListRelated = List.of();
        private Demons demons;

        private Builder(String name, DataType type) {
            this.name = requireNonNull(name, "name");
            this.type = requireNonNull(type, "type");
        }

        private Builder(Slot s) {
            this(s.name, s.facets.type);
            Facets f = s.facets;
            flags = f.flags;
            value = s.value;
            defaultValue = f.defaultValue;
            condition = f.condition;
            argument = f.argument;
            role = f.role;
            from = f.from;
            frameRelated = f.frameRelated;
            frameListRelated = f.frameListRelated;
            demons = f.demons;
        }

        public Builder type(DataType t) {
            this.type = requireNonNull(t, "type");
            return this;
        }

        public Builder value(Value v) {
            this.value = requireNonNull(v, "value");
            return this;
        }

        public Builder clearValue() {
            this.value = null;
            return this;
        }

        public Builder defaultValue(Value v) {
            this.defaultValue = requireNonNull(v, "defaultValue");
            return this;
        }

        public Builder clearDefault() {
            this.defaultValue = null;
            return this;
        }

        public Builder condition(Condition c) {
            this.condition = requireNonNull(c, "condition");
            return this;
        }

        public Builder argument(String a) {
            this.argument = requireNonNull(a, "argument");
            return this;
        }

        public Builder role(String r) {
            this.role = requireNonNull(r, "role");
            return this;
        }

        public Builder from(String f) {
            this.from = requireNonNull(f, "from");
            return this;
        }

        public Builder frameRelated(String f) {
            this.frameRelated = requireNonNull(f, "frameRelated");
            return this;
        }

        public Builder frameListRelated(List<String> frames) {
            this.frameListRelated = List.copyOf(frames);
            return this;
        }

        public Builder required(boolean on) {
            return flag(REQUIRED, on);
        }

        public Builder shared(boolean on) {
            return flag(SHARED, on);
        }

        public Builder unique(boolean on) {
            return flag(UNIQUE, on);
        }

        public Builder reactive(boolean on) {
            return flag(REACTIVE, on);
        }

        public Builder onNeeded(String script) {
            return demons(script, demons == null ? null : demons.onAdded, demons == null ? null : demons.onRemoved);
        }

        public Builder onAdded(String script) {
            return demons(demons == null ? null : demons.onNeeded, script, demons == null ? null : demons.onRemoved);
        }

        public Builder onRemoved(String script) {
            return demons(demons == null ? null : demons.onNeeded, demons == null ? null : demons.onAdded, script);
        }

        private Builder demons(String needed, String added, String removed) {
            demons = needed == null && added == null && removed == null ? null : new Demons(needed, added, removed);
            return this;
        }

        private Builder flag(int bit, boolean on) {
            flags = on ? flags | bit : flags & ~bit;
            return this;
        }

        /**
         * Builds the slot.
         *
         * @throws InvalidFrameException when a value and a default are both given, or a value does not fit the type
         */
        public Slot build() {
            if (!Names.isSlotName(name)) {
                throw new InvalidFrameException("'" + name + "' is not a valid slot name: scripts read slots as "
                        + "s.name, so use letters, digits, '_' and '$', starting with a letter, '_' or '$'.");
            }
            if (value != null && defaultValue != null) {
                throw bothValueAndDefault(name);
            }
            checkFits(name, type, value, "value");
            checkFits(name, type, defaultValue, "default");
            return new Slot(this);
        }
    }
}
