package org.kicnp.core.xml;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.kicnp.core.Change;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * A throwaway measurement, not a test: saves and loads a generated knowledge base of {@code N} frames (6 slots each,
 * a third of them instances, ISA chains 8 deep) and prints the times and the heap the loaded knowledge base keeps.
 * Run with {@code java -cp ... org.kicnp.core.xml.XmlBenchMain [frames] [rounds]}.
 */
public final class XmlBenchMain {
    private static final java.lang.management.ThreadMXBean CPU = java.lang.management.ManagementFactory.getThreadMXBean();

    private XmlBenchMain() {
    }

    static List<Frame> generate(int n) {
        int classes = n - n / 3;
        List<Frame> frames = new ArrayList<>(n);
        for (int i = 0; i < classes; i++) {
            Frame.Builder b = Frame.classFrame("C" + i);
            if (i % 8 != 0) {
                b.parent("C" + (i - 1));
            }
            String chainRoot = "C" + (i - i % 8);
            b.slot(Slot.builder("speed", DataType.FLOAT).defaultValue(Value.of(1.5)).build());
            b.slot(Slot.builder("name", DataType.STRING).required(true).build());
            b.slot(Slot.builder("count", DataType.INTEGER).value(Value.of((long) i)).build());
            b.slot(Slot.builder("on", DataType.BOOLEAN).build());
            b.slot(Slot.builder("tags", DataType.LIST).argument("TYPE_STR").build());
            b.slot(Slot.builder("peer", DataType.INSTANCE).argument(chainRoot).build());
            frames.add(b.build());
        }
        int leaves = classes / 8;
        for (int k = 0; k < n / 3; k++) {
            int chain = k % Math.max(1, leaves);
            String cls = "C" + (chain * 8 + 7);
            Frame.Builder b = Frame.instance("i" + k, cls);
            b.slot(Slot.ofValue("speed", DataType.FLOAT, Value.of(k * 0.5)));
            b.slot(Slot.ofValue("name", DataType.STRING, Value.of("robot " + k)));
            b.slot(Slot.ofValue("count", DataType.INTEGER, Value.of((long) k)));
            b.slot(Slot.ofValue("on", DataType.BOOLEAN, Value.of(k % 2 == 0)));
            b.slot(Slot.ofValue("tags", DataType.LIST, new Value.Lst(List.of(Value.of("a"), Value.of("b")))));
            if (k >= leaves) {
                b.slot(Slot.ofValue("peer", DataType.INSTANCE, Value.ref("i" + (k - leaves))));
            } else {
                b.slot(Slot.builder("peer", DataType.INSTANCE).build());
            }
            frames.add(b.build());
        }
        return frames;
    }

    public static void main(String[] args) throws Exception {
        int n = args.length > 0 ? Integer.parseInt(args[0]) : 100_000;
        int rounds = args.length > 1 ? Integer.parseInt(args[1]) : 3;
        Path file = Files.createTempFile("kicnp-bench", ".xml");
        try {
            List<Frame> frames = generate(n);
            KnowledgeBase.create().apply(frames.stream().map(Change.Add::new).toList());
            for (int r = 0; r < rounds; r++) {
                long t0 = System.nanoTime();
                long c0 = CPU.getCurrentThreadCpuTime();
                KnowledgeXmlWriter.write(frames, file);
                long t1 = System.nanoTime();
                long c1 = CPU.getCurrentThreadCpuTime();
                long p1 = processCpu();
                List<SourcedFrame> parsed = KnowledgeLoader.parse(List.of(file), KnowledgeBase.create());
                long t2 = System.nanoTime();
                long c2 = CPU.getCurrentThreadCpuTime();
                long p2 = processCpu();
                KnowledgeBase.create().apply(parsed.stream().map(s -> new Change.Add(s.frame())).toList());
                long t3 = System.nanoTime();
                long c3 = CPU.getCurrentThreadCpuTime();
                System.out.printf("round %d: %,d frames, file %,d bytes; save %d ms (cpu %d); parse %d ms (cpu %d, "
                        + "all threads %d) + apply %d ms (cpu %d)%n", r, n, Files.size(file), ms(t0, t1), ms(c0, c1),
                        ms(t1, t2), ms(c1, c2), ms(p1, p2), ms(t2, t3), ms(c2, c3));
            }
            frames = null;
            long base = heapAfterGc();
            KnowledgeBase loaded = KnowledgeBase.create();
            long t4 = System.nanoTime();
            KnowledgeLoader.load(loaded, List.of(file));
            long t5 = System.nanoTime();
            long after = heapAfterGc();
            System.out.printf("load %d ms; knowledge base of %,d frames retains %d MB%n", ms(t4, t5), loaded.size(),
                    (after - base) >> 20);
        } finally {
            Files.deleteIfExists(file);
        }
    }

    private static long heapAfterGc() throws InterruptedException {
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(100);
        }
        return Runtime.getRuntime().totalMemory() - Runtime.getRuntime().freeMemory();
    }

    /** CPU time of the whole process, GC and compiler threads included. */
    private static long processCpu() {
        return ((com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory
                .getOperatingSystemMXBean()).getProcessCpuTime();
    }

    private static long ms(long from, long to) {
        return (to - from) / 1_000_000;
    }
}
