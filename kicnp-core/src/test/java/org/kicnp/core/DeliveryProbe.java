package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.IntConsumer;
import java.util.stream.LongStream;

/**
 * For tests of delivery under concurrent commits: a listener recording each version it hears and whether two of its
 * calls ever overlapped, and a way to start writer threads together.
 */
final class DeliveryProbe implements KnowledgeListener {
    private final long start;
    private final List<Long> heard = Collections.synchronizedList(new ArrayList<>());
    private final AtomicInteger inside = new AtomicInteger();
    private final AtomicInteger overlaps = new AtomicInteger();

    private DeliveryProbe(long start) {
        this.start = start;
    }

    /** A probe listening to {@code kb} from its present version on. */
    static DeliveryProbe on(KnowledgeBase kb) {
        DeliveryProbe probe = new DeliveryProbe(kb.version());
        kb.addListener(probe);
        return probe;
    }

    @Override public void changed(ChangeSet cs) {
        if (inside.incrementAndGet() != 1) {
            overlaps.incrementAndGet();
        }
        heard.add(cs.version());
        Thread.onSpinWait();
        inside.decrementAndGet();
    }

    /** Asserts that the next {@code count} versions after the start were heard once each, in order, one at a time. */
    void assertHeardInOrder(int count) {
        assertThat(heard).isEqualTo(LongStream.rangeClosed(start + 1, start + count).boxed().toList());
        assertThat(overlaps).hasValue(0);
    }

    /** Runs {@code writer} (given its number) on {@code threads} platform threads released together; waits for all. */
    static void together(int threads, IntConsumer writer) throws InterruptedException {
        CyclicBarrier go = new CyclicBarrier(threads);
        List<Thread> writers = new ArrayList<>();
        for (int t = 0; t < threads; t++) {
            int id = t;
            writers.add(Thread.ofPlatform().start(() -> {
                try {
                    go.await();
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
                writer.accept(id);
            }));
        }
        for (Thread t : writers) {
            t.join();
        }
    }
}
