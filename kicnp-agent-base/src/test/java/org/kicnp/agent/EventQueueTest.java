package org.kicnp.agent;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;

/** An agent whose handlers cannot keep up: its reader goes on reading, and the oldest events are dropped, counted. */
class EventQueueTest {
    private static final int SENT = EventQueue.CAPACITY + 50;

    @Test
    void slowOnRelay_doesNotStallTheReader_andTheOldestRelaysAreDroppedAndCounted() throws Exception {
        try (FakeGateway server = new FakeGateway(peer -> {
            peer.register();
            for (int i = 1; i <= SENT; i++) {
                peer.send(Message.Relay.toAgent("", "bob", "alice", "n", Integer.toString(i)));
            }
            Message.Query q = (Message.Query) peer.readSkippingHeartbeats();
            peer.send(new Message.Frames(q.id(), List.of(), Optional.empty()));
            peer.drain();
        });
             SlowAgent a = new SlowAgent(AgentOptions.of("127.0.0.1", server.port(), "alice", AgentKind.USER, "t")
                     .withRequestTimeout(Duration.ofSeconds(5)))) {
            a.startAndAwait(Duration.ofSeconds(10));
            // Answered behind all the relays while onRelay is stuck on the first: the reader did not wait for it.
            assertThat(a.query("Cup")).isEmpty();
            assertThat(a.eventsDropped()).isGreaterThanOrEqualTo(SENT - EventQueue.CAPACITY - 1);
            a.gate.countDown();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (a.bodies.size() + a.eventsDropped() < SENT && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            assertThat(a.bodies.size() + a.eventsDropped()).isEqualTo(SENT);
            assertThat(a.bodies).hasSizeLessThanOrEqualTo(EventQueue.CAPACITY + 1).isSorted()
                    .endsWith(SENT); // the newest are kept
            assertThat(a.isConnected()).isTrue();
        }
    }

    /** An agent whose onRelay waits for the test's gate. */
    private static final class SlowAgent extends AgentBase {
        final CountDownLatch gate = new CountDownLatch(1);
        final List<Integer> bodies = new CopyOnWriteArrayList<>();

        SlowAgent(AgentOptions options) {
            super(options);
        }

        @Override protected void onRelay(Message.Relay relay) {
            try {
                gate.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            bodies.add(Integer.parseInt(relay.body()));
        }
    }
}
