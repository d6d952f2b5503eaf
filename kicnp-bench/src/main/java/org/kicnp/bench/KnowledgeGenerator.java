package org.kicnp.bench;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * Generates a knowledge base of a given size for benchmarks: a single IS-A tree exactly {@value #DEPTH} levels
 * deep (as wide as it must be to hold the classes), two thirds classes and one third instances spread over all
 * classes at random, every frame with six slots of mixed types. Each instance also holds an instance slot
 * referring to an earlier instance of its own class, which fits the slot's argument. Deterministic for a seed.
 */
final class KnowledgeGenerator {
    /** Levels in the IS-A tree, root included. */
    static final int DEPTH = 8;
    private static final String[] SLOT_NAMES = {
        "label", "count", "weight", "active", "title", "size", "ratio", "enabled", "note", "rank", "score", "visible",
    };
    private static final DataType[] SLOT_TYPES = {DataType.STRING, DataType.INTEGER, DataType.FLOAT, DataType.BOOLEAN};

    private final int frames;
    private final int classes;
    private final int branching;
    private final Random random;

    private KnowledgeGenerator(int frames, long seed) {
        if (frames < 3) {
            throw new IllegalArgumentException("A generated knowledge base needs at least 3 frames, not " + frames + ".");
        }
        this.frames = frames;
        this.classes = frames - frames / 3;
        this.branching = branchingFor(classes);
        this.random = new Random(seed);
    }

    static KnowledgeGenerator of(int frames, long seed) {
        return new KnowledgeGenerator(frames, seed);
    }

    int classCount() {
        return classes;
    }

    int instanceCount() {
        return frames - classes;
    }

    static String className(int k) {
        return "C" + k;
    }

    /** Depth of class {@code k} in the tree, the root being 0. */
    int depthOf(int k) {
        int depth = 0;
        for (int c = k; c > 0; c = (c - 1) / branching) {
            depth++;
        }
        return depth;
    }

    /** All frames, classes first (each after its parent), then instances. */
    List<Frame> generate() {
        List<Frame> out = new ArrayList<>(frames);
        for (int k = 0; k < classes; k++) {
            out.add(classFrame(k));
        }
        Map<Integer, String> lastInstanceOf = new HashMap<>();
        for (int i = 0; i < instanceCount(); i++) {
            int k = random.nextInt(classes);
            String name = "I" + i;
            out.add(instanceFrame(name, k, lastInstanceOf.get(k)));
            lastInstanceOf.put(k, name);
        }
        return out;
    }

    private Frame classFrame(int k) {
        Frame.Builder b = Frame.classFrame(className(k));
        if (k > 0) {
            b.parent(className((k - 1) / branching));
        }
        for (int j = 0; j < 6; j++) {
            Slot.Builder s = scalarSlot(k + j);
            b.slot(j == 5 ? s.defaultValue(valueFor(k + j, "C" + k)).build() : s.value(valueFor(k + j, "C" + k)).build());
        }
        return b.build();
    }

    private Frame instanceFrame(String name, int k, String peer) {
        Frame.Builder b = Frame.instance(name, className(k));
        for (int j = 0; j < 5; j++) {
            b.slot(scalarSlot(k + j + 1).value(valueFor(k + j + 1, name)).build());
        }
        Slot.Builder s = Slot.builder("peer", DataType.INSTANCE).argument(className(k));
        if (peer != null) {
            s.value(Value.ref(peer));
        }
        return b.slot(s.build()).build();
    }

    /** Slot {@code index} of the name pool; a name always has the same type, so overrides agree with parents. */
    private static Slot.Builder scalarSlot(int index) {
        int n = index % SLOT_NAMES.length;
        return Slot.builder(SLOT_NAMES[n], SLOT_TYPES[n % SLOT_TYPES.length]);
    }

    private Value valueFor(int index, String owner) {
        int n = index % SLOT_NAMES.length;
        return switch (SLOT_TYPES[n % SLOT_TYPES.length]) {
            case STRING -> Value.of(owner + " " + SLOT_NAMES[n] + " " + random.nextInt(1000));
            case INTEGER -> Value.of((long) random.nextInt(1_000_000));
            case FLOAT -> Value.of(random.nextInt(1_000_000) / 1000.0);
            case BOOLEAN -> Value.of(random.nextBoolean());
            default -> throw new IllegalStateException("No generated values of type " + SLOT_TYPES[n % SLOT_TYPES.length] + ".");
        };
    }

    /** The smallest branching factor with which a tree {@value #DEPTH} levels deep holds {@code classes}. */
    private static int branchingFor(int classes) {
        for (int b = 1; ; b++) {
            long capacity = 0;
            long level = 1;
            for (int d = 0; d < DEPTH; d++) {
                capacity += level;
                level *= b;
            }
            if (capacity >= classes) {
                return b;
            }
        }
    }
}
