package org.kicnp.agent;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/**
 * A flood while the event thread keeps taking events: each event is delivered or counted dropped, never both (the
 * oldest event, about to be dropped to make room, may be taken by the event thread at that very moment).
 */
class EventQueueRaceTest {

    @Test
    void aFloodWhileTheThreadKeepsTaking_deliversOrCountsEveryEventExactlyOnce() throws Exception {
        int sent = EventQueue.CAPACITY * 4;
        for (int round = 0; round < 15; round++) {
            AtomicLong delivered = new AtomicLong();
            try (EventQueue q = new EventQueue("flood")) {
                for (int i = 0; i < sent; i++) {
                    q.deliver(() -> {
                        delivered.incrementAndGet();
                        long until = System.nanoTime() + 300; // a handler a little slower than the flood
                        while (System.nanoTime() < until) {
                            Thread.onSpinWait();
                        }
                    });
                }
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
                while (delivered.get() + q.dropped() < sent && System.nanoTime() < deadline) {
                    Thread.sleep(5);
                }
                Thread.sleep(20); // anything counted twice would show by now
                assertThat(delivered.get() + q.dropped()).as("round %d: delivered %d, dropped %d", round,
                        delivered.get(), q.dropped()).isEqualTo(sent);
                assertThat(q.dropped()).as("the flood overflowed the queue").isPositive();
            }
        }
    }
}
