package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;

/** An agent that stops reading is bounded: messages to it are shed and counted, then it is dropped; others go on. */
class SlowConsumerTest {
    @Test
    void agentThatDoesNotRead_isShedThenDropped_whileSenderIsUnaffected() throws Exception {
        GatewayConfig config = GatewayConfig.defaults().withPort(0).withWriteBuffer(8 * 1024, 32 * 1024, 100);
        try (GatewayServer server = GatewayServer.start(config, GatewayEndToEndTest.AGENTS, KnowledgeBase.create(),
                FeedbackListener.NONE);
             RawClient bob = new RawClient(server.port(), 4096);
             UserAgent alice = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "alice", AgentKind.USER,
                     "alice-token"))) {
            bob.send(new Message.Hello("1", "bob", AgentKind.USER, "bob-token"));
            bob.send(new Message.Register("2", List.of()));
            assertThat(bob.read()).isInstanceOf(Message.AuthResult.class);
            assertThat(bob.read()).isEqualTo(new Message.Ack("2"));
            alice.startAndAwait(Duration.ofSeconds(10));

            String body = "x".repeat(8 * 1024);
            int sent = 0;
            while (server.metrics().slowConsumersDropped() == 0 && sent < 50_000) {
                alice.relayTo("bob", "flood", body);
                sent++;
            }

            assertThat(server.metrics().slowConsumersDropped()).isEqualTo(1);
            assertThat(server.metrics().shed()).isGreaterThanOrEqualTo(100);
            // Only what fit in the bounded buffers was ever queued for bob: far less than what alice sent.
            assertThat(sent).isGreaterThan(100).isLessThan(50_000);
            Eventually.await("bob is unregistered", () -> !server.registeredAgents().contains("bob"));
            List<Message> got = bob.readUntilClosed();
            assertThat(got.size()).isLessThan(sent);
            assertThat(alice.isConnected()).isTrue();
            assertThat(alice.query("Presence")).hasSize(1); // alice's own presence, bob's retracted
        }
    }
}
