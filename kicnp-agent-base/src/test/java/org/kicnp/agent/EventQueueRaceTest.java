package org.kicnp.agent;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/**
 * A flood while the event thread keeps taking events: each event is delivered or counted dropped, never both (the
 * oldest event, about to be dropped to make room, may be taken by the event thread at that very moment).
 *
 * <p>The first handler waits until twice {@value EventQueue#CAPACITY} events were delivered, so the queue is certain
 * to overflow whatever the pace of the host (left to race, a slow test thread could let the event thread keep up and
 * the flood never fill the queue); then the thread takes events while the rest of the flood goes on.
 */
class EventQueueRaceTest {

    @Test
    void aFloodWhileTheThreadKeepsTaking_deliversOrCountsEveryEventExactlyOnce() throws Exception {
        int sent = EventQueue.CAPACITY * 4;
        for (int round = 0; round < 15; round++) {
            AtomicLong delivered = new AtomicLong();
            CountDownLatch full = new CountDownLatch(1);
            try (EventQueue q = new EventQueue("flood")) {
                for (int i = 0; i < sent; i++) {
                    boolean first = i == 0;
                    q.deliver(() -> {
                        if (first) {
                            await(full);
                        }
                        delivered.incrementAndGet();
                        long until = System.nanoTime() + 300; // a handler a little slower than the flood
                        while (System.nanoTime() < until) {
                            Thread.onSpinWait();
                        }
                    });
                    if (i == 2 * EventQueue.CAPACITY) {
                        assertThat(q.dropped()).as("round %d: dropped while the first handler waits", round)
                                .isGreaterThanOrEqualTo(EventQueue.CAPACITY - 1);
                        full.countDown();
                    }
                }
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
                while (delivered.get() + q.dropped() < sent && System.nanoTime() < deadline) {
                    Thread.sleep(5);
                }
                Thread.sleep(20); // anything counted twice would show by now
                assertThat(delivered.get() + q.dropped()).as("round %d: delivered %d, dropped %d", round,
                        delivered.get(), q.dropped()).isEqualTo(sent);
            }
        }
    }

    private static void await(CountDownLatch latch) {
        try {
            if (!latch.await(20, TimeUnit.SECONDS)) {
                throw new IllegalStateException("the flood did not reach twice the queue's capacity in 20 s");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
