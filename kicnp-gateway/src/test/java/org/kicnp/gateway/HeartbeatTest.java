package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Message;

/** A silent connection is sent heartbeats, then closed with heartbeat_timeout. */
class HeartbeatTest {
    @Test
    void silentAgent_getsHeartbeatsThenTimeoutAndClose() throws Exception {
        GatewayConfig config = GatewayConfig.defaults().withPort(0).withHeartbeatTimeout(Duration.ofMillis(600));
        try (GatewayServer server = GatewayServer.start(config, GatewayEndToEndTest.AGENTS, KnowledgeBase.create(),
                FeedbackListener.NONE);
             RawClient raw = new RawClient(server.port())) {
            raw.send(new Message.Hello("1", "bob", AgentKind.USER, "bob-token"));
            List<Message> got = raw.readUntilClosed();
            assertThat(got).filteredOn(m -> m instanceof Message.Heartbeat).isNotEmpty();
            List<Message> rest = got.stream().filter(m -> !(m instanceof Message.Heartbeat)).toList();
            assertThat(rest).hasSize(2);
            assertThat(rest.getFirst()).isInstanceOf(Message.AuthResult.class);
            assertThat(rest.getLast()).isInstanceOfSatisfying(Message.ErrorReply.class,
                    e -> assertThat(e.code()).isEqualTo(ErrorCode.HEARTBEAT_TIMEOUT));
        }
    }
}
