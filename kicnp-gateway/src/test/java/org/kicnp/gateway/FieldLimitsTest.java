package org.kicnp.gateway;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Message;

/**
 * Names, actions, ids, a relay's subject and class names have a length limit of their own, far below the frame's: one
 * member longer than that is a {@code bad_message} naming the member and the limit, on every path a message takes (a
 * forwarded relay too).
 */
class FieldLimitsTest {
    private static final String LONG = "n".repeat(Message.MAX_NAME_LENGTH + 1);

    private final GatewayServer server = GatewayServer.start(GatewayConfig.defaults().withPort(0),
            GatewayEndToEndTest.AGENTS, KnowledgeBase.create(), FeedbackListener.NONE);

    @AfterEach
    void stop() {
        server.close();
    }

    private RawClient alice() throws IOException {
        RawClient c = new RawClient(server.port());
        c.send(new Message.Hello("h", "alice", AgentKind.USER, "alice-token"));
        assertThat(c.read()).isInstanceOf(Message.AuthResult.class);
        c.send(new Message.Register("r", List.of()));
        assertThat(c.read()).isEqualTo(new Message.Ack("r"));
        return c;
    }

    private static List<Message> refusal(String type, String member) {
        return List.of(Message.ErrorReply.of(ErrorCode.BAD_MESSAGE, "Bad '" + type + "' message: The member '" + member
                + "' is " + LONG.length() + " characters long; at most " + Message.MAX_NAME_LENGTH + " are allowed."));
    }

    @Test
    void hello_withAnAgentNameOverTheLimit_isABadMessage() throws IOException {
        try (RawClient raw = new RawClient(server.port())) {
            raw.sendPayload(("{\"v\":1,\"type\":\"hello\",\"id\":\"1\",\"agent\":\"" + LONG
                    + "\",\"kind\":\"user\",\"token\":\"t\"}").getBytes(UTF_8));
            assertThat(raw.readUntilClosed()).isEqualTo(refusal("hello", "agent"));
        }
    }

    @Test
    void hello_withAnAgentNameAtTheLimit_isCheckedAsAnyOther() throws IOException {
        String longest = "n".repeat(Message.MAX_NAME_LENGTH);
        try (RawClient raw = new RawClient(server.port())) {
            raw.send(new Message.Hello("1", longest, AgentKind.USER, "t"));
            assertThat(raw.readUntilClosed()).containsExactly(new Message.AuthResult("1", false, "kicnp",
                    Optional.of("Unknown agent '" + longest + "' or wrong token.")));
        }
    }

    /** A plain relay is routed without being decoded: its names are held to the same limit. */
    @Test
    void plainRelay_toAnAgentNameOverTheLimit_isABadMessage() throws IOException {
        try (RawClient alice = alice()) {
            alice.sendPayload(("{\"v\":1,\"type\":\"relay\",\"id\":\"2\",\"from\":\"alice\",\"toAgent\":\"" + LONG
                    + "\",\"subject\":\"s\",\"body\":\"b\"}").getBytes(UTF_8));
            assertThat(alice.readUntilClosed()).isEqualTo(refusal("relay", "toAgent"));
        }
    }

    @Test
    void command_withAnActionOverTheLimit_isABadMessage() throws IOException {
        try (RawClient alice = alice()) {
            alice.sendPayload(("{\"v\":1,\"type\":\"command\",\"id\":\"3\",\"robot\":\"scout\",\"action\":\"" + LONG
                    + "\",\"args\":{}}").getBytes(UTF_8));
            assertThat(alice.readUntilClosed()).isEqualTo(refusal("command", "action"));
        }
    }

    @Test
    void sensor_withANameOverTheLimit_isABadMessage() throws IOException {
        try (RawClient alice = alice()) {
            alice.sendPayload(("{\"v\":1,\"type\":\"sensor\",\"source\":\"alice\",\"sensor\":\"" + LONG
                    + "\",\"values\":[1]}").getBytes(UTF_8));
            assertThat(alice.readUntilClosed()).isEqualTo(refusal("sensor", "sensor"));
        }
    }

    @Test
    void query_withAnIdOverTheLimit_isABadMessage() throws IOException {
        try (RawClient alice = alice()) {
            alice.sendPayload(("{\"v\":1,\"type\":\"query\",\"id\":\"" + LONG + "\",\"ofClass\":\"Robot\"}")
                    .getBytes(UTF_8));
            assertThat(alice.readUntilClosed()).isEqualTo(refusal("query", "id"));
        }
    }

    @Test
    void plainRelay_withAnIdOverTheLimit_isABadMessage() throws IOException {
        try (RawClient alice = alice()) {
            alice.sendPayload(("{\"v\":1,\"type\":\"relay\",\"id\":\"" + LONG + "\",\"from\":\"alice\","
                    + "\"toKind\":\"user\",\"subject\":\"s\",\"body\":\"b\"}").getBytes(UTF_8));
            assertThat(alice.readUntilClosed()).isEqualTo(refusal("relay", "id"));
        }
    }

    @Test
    void plainRelay_withASubjectOverTheLimit_isABadMessage() throws IOException {
        try (RawClient alice = alice()) {
            alice.sendPayload(("{\"v\":1,\"type\":\"relay\",\"id\":\"4\",\"from\":\"alice\",\"toAgent\":\"bob\","
                    + "\"subject\":\"" + LONG + "\",\"body\":\"b\"}").getBytes(UTF_8));
            assertThat(alice.readUntilClosed()).isEqualTo(refusal("relay", "subject"));
        }
    }

    @Test
    void subscribe_toAClassNameOverTheLimit_isABadMessage() throws IOException {
        try (RawClient alice = alice()) {
            alice.sendPayload(("{\"v\":1,\"type\":\"subscribe\",\"id\":\"5\",\"ofClass\":\"" + LONG + "\"}")
                    .getBytes(UTF_8));
            assertThat(alice.readUntilClosed()).isEqualTo(refusal("subscribe", "ofClass"));
        }
    }
}
