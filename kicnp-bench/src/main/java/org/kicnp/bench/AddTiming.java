package org.kicnp.bench;

import com.sun.management.ThreadMXBean;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import org.kicnp.core.Change;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * Times the knowledge base's write path as the inference engine uses it: one {@link KnowledgeBase#add} per rule
 * firing, each a small RUNTIME instance frame with two INSTANCE slots referring to earlier instances, while the
 * knowledge base grows by that many frames. Classes: {@code Fact} with {@code Item} and {@code Derived} below it, and
 * {@code Pair} below {@code Derived} declaring {@code first: Fact} and {@code second: Item}. {@value #ITEMS} items come
 * first (one batch); pair {@code i} then refers to pair {@code i / 2} (an item for the first two) and to item
 * {@code i % ITEMS}, so each pair is referred to by up to two later pairs and each item by many. The time per add
 * includes building the frame, as the engine does; the bytes are what the adding thread allocates per add.
 */
final class AddTiming {
    static final int ITEMS = 1_000;

    /** The median over rounds of the wall-clock and thread-CPU microseconds, and the bytes allocated, per add. */
    record Result(int adds, double usPerAdd, double cpuUsPerAdd, double bytesPerAdd) {
    }

    private AddTiming() {
    }

    /** One untimed warm-up round of a tenth of the adds, then {@code rounds} timed ones on fresh knowledge bases. */
    static Result measure(int adds, int rounds) {
        run(Math.max(1, adds / 10));
        Samples wall = new Samples();
        Samples cpu = new Samples();
        Samples bytes = new Samples();
        for (int r = 0; r < rounds; r++) {
            System.gc();
            Round round = run(adds);
            wall.add(round.wallNanos() / 1000.0 / adds);
            cpu.add(round.cpuNanos() / 1000.0 / adds);
            bytes.add((double) round.bytes() / adds);
        }
        return new Result(adds, wall.median(), cpu.median(), bytes.median());
    }

    private record Round(long wallNanos, long cpuNanos, long bytes) {
    }

    private static Round run(int adds) {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.apply(schema());
        ThreadMXBean threads = (ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().threadId();
        long cpuStart = threads.getCurrentThreadCpuTime();
        long bytesStart = threads.getThreadAllocatedBytes(thread);
        long start = System.nanoTime();
        for (int i = 0; i < adds; i++) {
            kb.add(pair(i));
        }
        long wall = System.nanoTime() - start;
        long cpu = threads.getCurrentThreadCpuTime() - cpuStart;
        long bytes = threads.getThreadAllocatedBytes(thread) - bytesStart;
        if (kb.size() != adds + ITEMS + 4) {
            throw new IllegalStateException("The knowledge base holds " + kb.size() + " frames after " + adds
                    + " adds: the benchmark would measure the wrong thing.");
        }
        return new Round(wall, cpu, bytes);
    }

    private static List<Change> schema() {
        List<Change> out = new ArrayList<>(ITEMS + 4);
        out.add(new Change.Add(Frame.classFrame("Fact").build()));
        out.add(new Change.Add(Frame.classFrame("Item").parent("Fact").build()));
        out.add(new Change.Add(Frame.classFrame("Derived").parent("Fact").build()));
        out.add(new Change.Add(Frame.classFrame("Pair").parent("Derived")
                .slot(Slot.builder("first", DataType.INSTANCE).argument("Fact").required(true).build())
                .slot(Slot.builder("second", DataType.INSTANCE).argument("Item").required(true).build())
                .build()));
        for (int i = 0; i < ITEMS; i++) {
            out.add(new Change.Add(Frame.instance("item" + i, "Item").provenance(Provenance.RUNTIME).build()));
        }
        return out;
    }

    private static Frame pair(int i) {
        String first = i < 2 ? "item" + i : "pair" + i / 2;
        return Frame.instance("pair" + i, "Pair").provenance(Provenance.RUNTIME)
                .slot(Slot.builder("first", DataType.INSTANCE).value(Value.ref(first)).build())
                .slot(Slot.builder("second", DataType.INSTANCE).value(Value.ref("item" + i % ITEMS)).build())
                .build();
    }
}
