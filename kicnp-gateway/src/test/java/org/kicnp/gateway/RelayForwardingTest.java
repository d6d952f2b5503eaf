package org.kicnp.gateway;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.DataInputStream;
import java.io.IOException;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.Message;

/**
 * The relay hot path over real sockets: a plain relay that names its sender is forwarded byte for byte, and every
 * other relay — a wrong sender, an extra member — is decoded and delivered with the sender the hub authenticated.
 */
class RelayForwardingTest {
    private final GatewayServer server = GatewayServer.start(GatewayConfig.defaults().withPort(0),
            AgentDirectory.empty().with("alice", "a", AgentKind.USER).with("bob", "b", AgentKind.USER)
                    .with("carol", "c", AgentKind.USER),
            KnowledgeBase.create(), FeedbackListener.NONE);

    @AfterEach
    void stop() {
        server.close();
    }

    private RawClient agent(String name, String token) throws IOException {
        RawClient c = new RawClient(server.port());
        c.send(new Message.Hello("h", name, AgentKind.USER, token));
        assertThat(c.read()).isInstanceOf(Message.AuthResult.class);
        c.send(new Message.Register("r", List.of()));
        assertThat(c.read()).isEqualTo(new Message.Ack("r"));
        return c;
    }

    private static byte[] rawPayload(RawClient c) throws IOException {
        return Framing.read(new DataInputStream(c.socket.getInputStream()), Framing.DEFAULT_MAX_FRAME_BYTES);
    }

    @Test
    void plainRelay_namingItsSender_arrivesByteForByte_andIsAcked() throws IOException {
        try (RawClient alice = agent("alice", "a"); RawClient bob = agent("bob", "b")) {
            byte[] sent = ("{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"alice\",\"toAgent\":\"bob\","
                    + "\"subject\":\"say\",\"body\":\"h\\u00e9llo\"}").getBytes(UTF_8);
            alice.sendPayload(sent);
            assertThat(alice.read()).isEqualTo(new Message.Ack("1"));
            assertThat(rawPayload(bob)).isEqualTo(sent);
        }
    }

    @Test
    void relay_namingAnotherSender_isDeliveredWithTheAuthenticatedOne() throws IOException {
        try (RawClient alice = agent("alice", "a"); RawClient bob = agent("bob", "b")) {
            alice.send(Message.Relay.toAgent("2", "carol", "bob", "say", "it was carol"));
            assertThat(alice.read()).isEqualTo(new Message.Ack("2"));
            assertThat(bob.read()).isEqualTo(Message.Relay.toAgent("2", "alice", "bob", "say", "it was carol"));
        }
    }

    @Test
    void relay_withRepeatedFrom_isDeliveredWithTheAuthenticatedSenderOnly() throws IOException {
        try (RawClient alice = agent("alice", "a"); RawClient bob = agent("bob", "b")) {
            alice.sendPayload(("{\"v\":1,\"type\":\"relay\",\"id\":\"3\",\"from\":\"carol\",\"from\":\"alice\","
                    + "\"toAgent\":\"bob\",\"subject\":\"s\",\"body\":\"b\",\"extra\":1}").getBytes(UTF_8));
            assertThat(alice.read()).isEqualTo(new Message.Ack("3"));
            String delivered = new String(rawPayload(bob), UTF_8);
            assertThat(delivered).doesNotContain("carol").doesNotContain("extra").contains("\"from\":\"alice\"");
        }
    }

    @Test
    void plainRelay_toKind_reachesEveryOtherAgentOfThatKind() throws IOException {
        try (RawClient alice = agent("alice", "a"); RawClient bob = agent("bob", "b");
             RawClient carol = agent("carol", "c")) {
            Message.Relay all = Message.Relay.toKind("4", "alice", AgentKind.USER, "all", "hands");
            alice.send(all);
            assertThat(alice.read()).isEqualTo(new Message.Ack("4"));
            assertThat(bob.read()).isEqualTo(all);
            assertThat(carol.read()).isEqualTo(all);
            alice.send(new Message.Query("q", "NoSuchFrame")); // alice's next message is the answer, not her relay
            assertThat(alice.read()).isNotInstanceOf(Message.Relay.class);
        }
    }

    /** Whether the relay is forwarded as it is (it names its sender) or decoded, nobody receiving it is an error. */
    @Test
    void relay_toKindWithNoOtherAgentOfIt_isRefusedWithUnknownAgent_onBothPaths() throws IOException {
        try (RawClient alice = agent("alice", "a")) {
            String nobody = "No other agent of kind 'robot' is registered, so nobody received the relay.";
            alice.send(Message.Relay.toKind("8", "alice", AgentKind.ROBOT, "stop", "now"));
            assertThat(alice.read()).isEqualTo(Message.ErrorReply.to("8", ErrorCode.UNKNOWN_AGENT, nobody));
            alice.send(Message.Relay.toKind("9", "carol", AgentKind.ROBOT, "stop", "now"));
            assertThat(alice.read()).isEqualTo(Message.ErrorReply.to("9", ErrorCode.UNKNOWN_AGENT, nobody));
            alice.send(Message.Relay.toKind("", "alice", AgentKind.ROBOT, "stop", "now"));
            assertThat(alice.read()).isEqualTo(Message.ErrorReply.of(ErrorCode.UNKNOWN_AGENT, nobody));
            alice.send(Message.Relay.toKind("10", "alice", AgentKind.USER, "all", "alone")); // alice is its only user
            assertThat(alice.read()).isEqualTo(Message.ErrorReply.to("10", ErrorCode.UNKNOWN_AGENT,
                    "No other agent of kind 'user' is registered, so nobody received the relay."));
        }
    }

    @Test
    void relay_withEmptyId_isDeliveredWithoutAck_andRefusedWithAnErrorWithoutId() throws IOException {
        try (RawClient alice = agent("alice", "a"); RawClient bob = agent("bob", "b")) {
            Message.Relay quiet = Message.Relay.toAgent("", "alice", "bob", "say", "no ack");
            alice.send(quiet);
            alice.send(Message.Relay.toAgent("", "alice", "dave", "say", "nobody"));
            assertThat(bob.read()).isEqualTo(quiet);
            assertThat(alice.read()).isInstanceOfSatisfying(Message.ErrorReply.class, e -> {
                assertThat(e.id()).isEmpty();
                assertThat(e.message()).isEqualTo("No agent 'dave' is registered.");
            });
            alice.send(Message.Relay.toAgent("7", "alice", "bob", "say", "with ack"));
            assertThat(alice.read()).isEqualTo(new Message.Ack("7")); // nothing else came before it
        }
    }

    @Test
    void plainRelay_beforeHello_isRefused() throws IOException {
        try (RawClient eve = new RawClient(server.port())) {
            eve.send(Message.Relay.toAgent("5", "eve", "bob", "s", "b"));
            assertThat(eve.readUntilClosed()).singleElement().isInstanceOfSatisfying(Message.ErrorReply.class,
                    e -> assertThat(e.message()).isEqualTo("Send 'hello' first: 'relay' before authentication."));
        }
    }

    @Test
    void relay_toAgentNotRegistered_getsUnknownAgent() throws IOException {
        try (RawClient alice = agent("alice", "a")) {
            alice.send(Message.Relay.toAgent("6", "alice", "bob", "s", "b"));
            assertThat(alice.read()).isInstanceOfSatisfying(Message.ErrorReply.class, e -> {
                assertThat(e.id()).isEqualTo(Optional.of("6"));
                assertThat(e.message()).isEqualTo("No agent 'bob' is registered.");
            });
        }
    }
}
