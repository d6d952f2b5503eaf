package org.kicnp.core;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;

/**
 * A prepared add of instance frames of one class whose slots are instance slots of that class, in a fixed order — a
 * JDBC {@code PreparedStatement} for the instances an inference engine derives: {@link KnowledgeBase#addInstance}
 * checks the class and its slot declarations against the knowledge base once, keeps what it found while no class
 * changes, and then checks and indexes each instance with no look-up of its class, slot declarations or name check
 * of its own (the name is the class's name, '-' and a number).
 *
 * <p>Made once per behavior frame, with no knowledge base; immutable for its users. What a knowledge base resolved is
 * kept here as one immutable {@code Resolution}, replaced under that knowledge base's write lock.
 */
public final class InstanceShape {
    private final String className;
    private final List<Slot> templates;
    /** What a knowledge base last found for this shape, or null. */
    private volatile Resolution resolution;

    /**
     * What a knowledge base found: the node of the shape's class, and the checked class each slot's value must be an
     * instance of; valid while that knowledge base's classes are as they were ({@code epoch}).
     */
    record Resolution(NodeIndex nodes, long epoch, Node classNode, ClassInfo[] arguments) {
    }

    private InstanceShape(String className, List<Slot> templates) {
        this.className = className;
        this.templates = templates;
    }

    /**
     * The shape of instances of {@code className} whose slots are the instance slots {@code slots}, in that order.
     *
     * @throws IllegalArgumentException for an invalid class or slot name, or a slot named twice
     */
    public static InstanceShape of(String className, List<String> slots) {
        requireNonNull(className, "className");
        if (!Names.isFrameName(className)) {
            throw new IllegalArgumentException("'" + className + "' is not a valid frame name.");
        }
        if (new HashSet<>(slots).size() != slots.size()) {
            throw new IllegalArgumentException("Instance shape of '" + className + "' names a slot twice: " + slots
                    + ".");
        }
        List<Slot> templates = new ArrayList<>(slots.size());
        for (String s : slots) {
            try {
                templates.add(Slot.builder(s, DataType.INSTANCE).build());
            } catch (InvalidFrameException e) {
                throw new IllegalArgumentException(e.getMessage(), e);
            }
        }
        return new InstanceShape(className, List.copyOf(templates));
    }

    public String className() {
        return className;
    }

    /** The slots, each an instance slot with no value, in order. */
    public List<Slot> templates() {
        return templates;
    }

    /**
     * The instance frame named {@code name} with {@code values} in the slots, made and checked as
     * {@link Frame#instance(String, String, Provenance, Slot...)} makes any (runtime provenance).
     *
     * @throws InvalidFrameException when the name is not valid or a value does not fit an instance slot
     */
    Frame frame(String name, Value[] values) {
        return Frame.instance(name, className, Provenance.RUNTIME, slots(values));
    }

    /** The slots holding {@code values}. */
    Slot[] slots(Value[] values) {
        checkCount(values);
        Slot[] slots = new Slot[values.length];
        for (int i = 0; i < values.length; i++) {
            slots[i] = templates.get(i).withValue(values[i]);
        }
        return slots;
    }

    /**
     * {@link #slots(Value[])} as an immutable list: for one or two slots (most behavior frames) made without the
     * array, which a list of them would only copy.
     */
    List<Slot> slotList(Value[] values) {
        if (values.length > 2) {
            return List.of(slots(values));
        }
        checkCount(values);
        return switch (values.length) {
            case 0 -> List.of();
            case 1 -> List.of(templates.get(0).withValue(values[0]));
            default -> List.of(templates.get(0).withValue(values[0]), templates.get(1).withValue(values[1]));
        };
    }

    private void checkCount(Value[] values) {
        if (values.length != templates.size()) {
            throw new IllegalArgumentException("Instance shape of '" + className + "' has " + templates.size()
                    + " slots, not " + values.length + ".");
        }
    }

    /**
     * Whether {@code name} is this class's name, '-' and digits — a valid frame name, as the class's name is — given
     * its {@linkplain NameTable#numberOf number} (the digits after its last '-', or -1).
     */
    boolean names(String name, int number) {
        int n = className.length();
        return number >= 0 && name.length() > n + 1 && name.charAt(n) == '-' && name.lastIndexOf('-') == n
                && name.startsWith(className);
    }

    Resolution resolution() {
        return resolution;
    }

    void resolved(Resolution r) {
        resolution = r;
    }

    @Override public String toString() {
        return "InstanceShape[" + className + templates.stream().map(Slot::name).toList() + "]";
    }
}
