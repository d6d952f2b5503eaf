package org.kicnp.agent;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;

/** What the options change in a running agent, against a scripted server on loopback. */
class AgentOptionsTest {
    private static final Duration INTERVAL = Duration.ofMillis(100);
    private static final Duration SILENCE = Duration.ofMillis(600);

    /**
     * With {@code withHeartbeat(100 ms, 600 ms)} an idle agent sends a heartbeat about every 100 ms, and a server that
     * goes silent (it reads but never answers) is taken for lost after 600 ms, not the default 40 s: the agent
     * connects again. The defaults (every 5 s, 40 s of silence) would send none in that time and wait on.
     */
    @Test
    void withHeartbeat_sendsHeartbeatsAtTheInterval_andLeavesASilentServerAfterTheSilence() throws Exception {
        List<Long> heartbeats = new CopyOnWriteArrayList<>();
        CompletableFuture<Long> silentFor = new CompletableFuture<>();
        try (FakeGateway server = new FakeGateway(
                peer -> {
                    peer.register();
                    long registered = System.nanoTime();
                    try {
                        while (true) {
                            if (peer.read() instanceof Message.Heartbeat) {
                                heartbeats.add(System.nanoTime());
                            }
                        }
                    } catch (IOException closedByTheAgent) {
                        silentFor.complete(System.nanoTime() - registered);
                    }
                },
                peer -> {
                    peer.register();
                    peer.drain();
                });
             UserAgent a = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "alice", AgentKind.USER, "t")
                     .withHeartbeat(INTERVAL, SILENCE).withBackoff(Duration.ofMillis(10), Duration.ofMillis(50)))) {
            a.startAndAwait(Duration.ofSeconds(10));
            long nanos = silentFor.get(10, TimeUnit.SECONDS);
            assertThat(Duration.ofNanos(nanos)).isBetween(SILENCE.minusMillis(50), SILENCE.plusSeconds(3));
            assertThat(heartbeats).hasSizeGreaterThanOrEqualTo(3);
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (!(server.connections() == 2 && a.isConnected()) && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            assertThat(server.connections()).isEqualTo(2);
            assertThat(a.isConnected()).isTrue();
        }
    }
}
