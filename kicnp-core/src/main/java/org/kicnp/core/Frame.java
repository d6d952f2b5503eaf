package org.kicnp.core;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * A frame: the items of the paper's Table 1 (name, type, A-kind-of, has-part, semantic links, slots). Descendants
 * are derived by the {@link KnowledgeBase} from the A-kind-of items, never stored twice. Immutable; an edit is a
 * new frame that replaces the old one. Slot order is kept as written.
 */
public final class Frame {
    private final String name;
    private final FrameKind kind;
    private final String parent;
    /** Parts and semantic links, in one field: most frames (every runtime instance) have none, and share one. */
    private final Structure structure;
    private final List<Slot> slots;
    private final Provenance provenance;
    private final int priority;
    /**
     * The knowledge-base node this frame was last made the frame of ({@link Node#find}): a short cut to it for a
     * caller that refers to this frame, checked before use. Not part of the frame's value.
     */
    Node node;
    /**
     * {@link NameTable#numberOf(String)} of the name, plus 2; 0 until asked ({@link NameTable#numberOf(Frame)}). The
     * indexes of the knowledge base and of an engine each read a name's number: kept here, the name's characters are
     * read once, where each read of a name made long before was a cache miss. A benign race, as String's hash: every
     * thread that computes it stores the same value. Not part of the frame's value.
     */
    int nameNumber;

    private Frame(Builder b) {
        this.name = b.name;
        this.kind = b.kind;
        this.parent = b.parent;
        this.structure = Structure.of(copy(b.parts), copy(b.linksTo), copy(b.linksFrom));
        this.slots = copy(b.slots);
        this.provenance = b.provenance;
        this.priority = b.priority;
    }

    /** An instance frame with no parts or links, of priority 0: see {@link #instance(String, String, Provenance, Slot...)}. */
    private Frame(String name, String parent, List<Slot> slots, Provenance provenance) {
        this.name = name;
        this.kind = FrameKind.INSTANCE;
        this.parent = parent;
        this.structure = Structure.NONE;
        this.slots = slots;
        this.provenance = provenance;
        this.priority = 0;
    }

    /**
     * A runtime instance frame with these slots, made without the checks of {@link #instance(String, String,
     * Provenance, Slot...)}: for a knowledge base that has made those checks another way ({@link InstanceShape}).
     * {@code slots} must be immutable ({@link List#of}).
     */
    static Frame plain(String name, String parent, List<Slot> slots) {
        return new Frame(name, parent, slots, Provenance.RUNTIME);
    }

    /** An immutable copy; most frames have no parts or links, so a builder leaves those lists null until used. */
    private static <T> List<T> copy(List<T> items) {
        return items == null || items.isEmpty() ? List.of() : List.copyOf(items);
    }

    /**
     * A valid frame name for any text (a name heard, a label typed): each run of characters a frame name cannot hold
     * becomes one '_', and a '_' goes first when the text does not start with a letter; "José O'Brien" gives
     * "José_O_Brien". The same text always gives the same name.
     */
    public static String nameFor(String text) {
        return Names.toFrameName(requireNonNull(text, "text"));
    }

    /** Starts a class frame. */
    public static Builder classFrame(String name) {
        return new Builder(name, FrameKind.CLASS);
    }

    /** Starts an instance frame of the given class. */
    public static Builder instance(String name, String ofClass) {
        return new Builder(name, FrameKind.INSTANCE).parent(ofClass);
    }

    /**
     * The instance frame that {@code instance(name, ofClass).provenance(provenance)} with {@code slots} added in
     * order builds, checked the same way, made without a builder and its copy of the slots: an inference engine
     * makes one for every firing. Unlike the builder, which keeps the last of two slots of one name, this refuses
     * them.
     *
     * @throws InvalidFrameException for a blank or invalid name, a frame that is its own class, or two slots with one
     *     name
     */
    public static Frame instance(String name, String ofClass, Provenance provenance, Slot... slots) {
        String n = requireNonNull(name, "name").strip();
        requireNonNull(ofClass, "parent");
        requireNonNull(provenance, "provenance");
        List<Slot> list = List.of(slots); // one or two slots: no array is kept; and no null slot passes
        check(n, FrameKind.INSTANCE, ofClass, list);
        return new Frame(n, ofClass, list, provenance);
    }

    /**
     * The checks every frame passes when it is built.
     *
     * @throws InvalidFrameException for a blank or invalid name, an instance without a class, a frame that is its
     *     own parent, or two slots with one name
     */
    private static void check(String name, FrameKind kind, String parent, List<Slot> slots) {
        if (name.isEmpty()) {
            throw new InvalidFrameException("A frame needs a name.");
        }
        if (!Names.isFrameName(name)) {
            throw new InvalidFrameException("'" + name + "' is not a valid frame name: use letters, digits, "
                    + "'_' and '-', starting with a letter or '_'.");
        }
        if (kind == FrameKind.INSTANCE && parent == null) {
            throw new InvalidFrameException("Instance frame '" + name + "' needs a class in its A-kind-of (ISA).");
        }
        if (name.equals(parent)) {
            throw new InvalidFrameException("Frame '" + name + "' cannot be a kind of itself.");
        }
        checkSlotNamesUnique(name, slots);
    }

    /** Frames have a handful of slots: comparing pairs beats building a hash set for each frame built. */
    private static void checkSlotNamesUnique(String frame, List<Slot> slots) {
        int n = slots.size();
        Set<String> seen = n > 16 ? new HashSet<>() : null;
        for (int i = 0; i < n; i++) {
            String slotName = slots.get(i).name();
            boolean twice;
            if (seen != null) {
                twice = !seen.add(slotName);
            } else {
                twice = false;
                for (int j = 0; j < i && !twice; j++) {
                    twice = slots.get(j).name().equals(slotName);
                }
            }
            if (twice) {
                throw new InvalidFrameException("Frame '" + frame + "' has two slots named '" + slotName + "'.");
            }
        }
    }

    public static Builder builder(String name, FrameKind kind) {
        return new Builder(name, kind);
    }

    public Builder toBuilder() {
        return new Builder(this);
    }

    public String name() {
        return name;
    }

    public FrameKind kind() {
        return kind;
    }

    public boolean isInstance() {
        return kind == FrameKind.INSTANCE;
    }

    public boolean isClass() {
        return kind == FrameKind.CLASS;
    }

    /** The A-kind-of item: the parent class, or empty for a root frame. */
    public Optional<String> parent() {
        return Optional.ofNullable(parent);
    }

    /** The parent's name or null: {@link #parent()} without an Optional, for the knowledge base's hot paths. */
    String parentOrNull() {
        return parent;
    }

    /** The has-part item: frames this frame is made of. */
    public List<String> parts() {
        return structure.parts();
    }

    /** Semantic links this frame declares to other frames. */
    public List<SemanticLink> linksTo() {
        return structure.linksTo();
    }

    /** Semantic links this frame declares from other frames. */
    public List<SemanticLink> linksFrom() {
        return structure.linksFrom();
    }

    /** The slots declared on this frame itself, in written order; inherited slots are the knowledge base's. */
    public List<Slot> slots() {
        return slots;
    }

    /** The slot declared on this frame with that name, not looking up the IS-A chain. */
    public Optional<Slot> ownSlot(String slotName) {
        return Optional.ofNullable(ownSlotOrNull(slotName));
    }

    /** {@link #ownSlot} without an Optional, for the knowledge base's hot paths. */
    Slot ownSlotOrNull(String slotName) {
        for (int i = 0, n = slots.size(); i < n; i++) {
            Slot s = slots.get(i);
            if (s.name().equals(slotName)) {
                return s;
            }
        }
        return null;
    }

    public Provenance provenance() {
        return provenance;
    }

    public boolean learned() {
        return provenance == Provenance.LEARNED;
    }

    /** Explicit priority for conflict resolution in the inference engine; higher fires first. Default 0. */
    public int priority() {
        return priority;
    }

    /** A copy with one slot added or replaced (by name). */
    public Frame withSlot(Slot slot) {
        return toBuilder().slot(slot).build();
    }

    /**
     * A frame's parts and semantic links (immutable lists). Kept apart from the frame's other fields, one object for all
     * frames with none, so that each of the many instance frames a run derives is 48 bytes rather than 56.
     */
    private record Structure(List<String> parts, List<SemanticLink> linksTo, List<SemanticLink> linksFrom) {
        static final Structure NONE = new Structure(List.of(), List.of(), List.of());

        static Structure of(List<String> parts, List<SemanticLink> linksTo, List<SemanticLink> linksFrom) {
            return parts.isEmpty() && linksTo.isEmpty() && linksFrom.isEmpty() ? NONE
                    : new Structure(parts, linksTo, linksFrom);
        }
    }

    @Override public boolean equals(Object o) {
        return o instanceof Frame f && name.equals(f.name) && kind == f.kind && java.util.Objects.equals(parent, f.parent)
                && structure.equals(f.structure)
                && slots.equals(f.slots) && provenance == f.provenance && priority == f.priority;
    }

    @Override public int hashCode() {
        return name.hashCode() * 31 + slots.hashCode();
    }

    @Override public String toString() {
        return (kind == FrameKind.CLASS ? "class " : "instance ") + name + (parent != null ? " : " + parent : "");
    }

    /** Builds a {@link Frame}, checking what can be checked without the rest of the knowledge base. */
    public static final class Builder {
        private final String name;
        private FrameKind kind;
        private String parent;
        // Created on first use: building a frame is on the path of every load and every rule firing.
        private List<String> parts;
        private List<SemanticLink> linksTo;
        private List<SemanticLink> linksFrom;
        private final List<Slot> slots = new ArrayList<>(6);
        private Provenance provenance = Provenance.DECLARED;
        private int priority;

        private Builder(String name, FrameKind kind) {
            this.name = requireNonNull(name, "name").strip();
            this.kind = requireNonNull(kind, "kind");
        }

        private Builder(Frame f) {
            this(f.name, f.kind);
            parent = f.parent;
            parts = f.parts().isEmpty() ? null : new ArrayList<>(f.parts());
            linksTo = f.linksTo().isEmpty() ? null : new ArrayList<>(f.linksTo());
            linksFrom = f.linksFrom().isEmpty() ? null : new ArrayList<>(f.linksFrom());
            slots.addAll(f.slots);
            provenance = f.provenance;
            priority = f.priority;
        }

        public Builder kind(FrameKind k) {
            this.kind = requireNonNull(k, "kind");
            return this;
        }

        public Builder parent(String p) {
            this.parent = requireNonNull(p, "parent");
            return this;
        }

        public Builder root() {
            this.parent = null;
            return this;
        }

        public Builder part(String frame) {
            if (parts == null) {
                parts = new ArrayList<>();
            }
            parts.add(requireNonNull(frame, "frame"));
            return this;
        }

        public Builder linkTo(Relation relation, String frame) {
            if (linksTo == null) {
                linksTo = new ArrayList<>();
            }
            linksTo.add(new SemanticLink(relation, frame));
            return this;
        }

        public Builder linkFrom(Relation relation, String frame) {
            if (linksFrom == null) {
                linksFrom = new ArrayList<>();
            }
            linksFrom.add(new SemanticLink(relation, frame));
            return this;
        }

        /** Adds a slot, replacing a slot of the same name if there is one. */
        public Builder slot(Slot slot) {
            requireNonNull(slot, "slot");
            for (int i = 0; i < slots.size(); i++) {
                if (slots.get(i).name().equals(slot.name())) {
                    slots.set(i, slot);
                    return this;
                }
            }
            slots.add(slot);
            return this;
        }

        public Builder removeSlot(String slotName) {
            slots.removeIf(s -> s.name().equals(slotName));
            return this;
        }

        public Builder provenance(Provenance p) {
            this.provenance = requireNonNull(p, "provenance");
            return this;
        }

        public Builder priority(int p) {
            this.priority = p;
            return this;
        }

        /**
         * Builds the frame.
         *
         * @throws InvalidFrameException for a blank name, an instance without a class, a frame that is its own
         *     parent, or two slots with one name
         */
        public Frame build() {
            check(name, kind, parent, slots);
            return new Frame(this);
        }
    }
}
