package org.kicnp.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;

/**
 * Measures the heap that is still reachable: collects garbage until the used heap stops shrinking, then reads
 * it. The difference of two such readings, one before building a structure and one after with only that
 * structure kept, is the structure's retained size.
 */
final class HeapMeter {
    private static final int MAX_COLLECTIONS = 8;
    private static final long SETTLED_BYTES = 256 * 1024;

    private HeapMeter() {
    }

    /** Used heap in bytes after forcing garbage collection a few times. */
    static long usedAfterGc() {
        MemoryMXBean memory = ManagementFactory.getMemoryMXBean();
        long best = Long.MAX_VALUE;
        for (int i = 0; i < MAX_COLLECTIONS; i++) {
            memory.gc();
            pause();
            long used = memory.getHeapMemoryUsage().getUsed();
            boolean settled = best - used < SETTLED_BYTES && i >= 2;
            best = Math.min(best, used);
            if (settled) {
                break;
            }
        }
        return best;
    }

    private static void pause() {
        try {
            Thread.sleep(30);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
