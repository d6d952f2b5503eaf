package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;

/** The gateway's socket transports: chosen by name, the best one by default, and each one relays over real sockets. */
class TransportTest {
    @Test
    void parse_readsEachLabel_andAutoIsTheBestAvailable() {
        for (Transport t : Transport.values()) {
            assertThat(Transport.parse(t.label())).isEqualTo(t);
            assertThat(Transport.parse(" " + t.label().toUpperCase(java.util.Locale.ROOT) + " ")).isEqualTo(t);
        }
        assertThat(Transport.parse("auto")).isEqualTo(Transport.best());
        assertThat(Transport.best().isAvailable()).isTrue();
        assertThat(GatewayConfig.defaults().transport()).isEqualTo(Transport.best());
    }

    @Test
    void parse_unknownName_listsTheChoices() {
        assertThatThrownBy(() -> Transport.parse("carrier-pigeon"))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("carrier-pigeon")
                .hasMessageContaining("auto, io_uring, epoll, nio");
    }

    @Test
    void nio_worksEverywhere_andTheBestPrefersNativeTransportsInOrder() {
        assertThat(Transport.NIO.isAvailable()).isTrue();
        assertThat(Transport.NIO.unavailabilityCause()).isEmpty();
        Transport expected = Transport.IO_URING.isAvailable() ? Transport.IO_URING
                : Transport.EPOLL.isAvailable() ? Transport.EPOLL : Transport.NIO;
        assertThat(Transport.best()).isEqualTo(expected);
    }

    @ParameterizedTest
    @EnumSource(Transport.class)
    void gateway_onEachAvailableTransport_authenticatesAndRelays(Transport transport) throws IOException {
        assumeTrue(transport.isAvailable(), () -> transport.label() + " does not work here: "
                + transport.unavailabilityCause().orElse(""));
        try (GatewayServer server = GatewayServer.start(GatewayConfig.defaults().withPort(0).withTransport(transport),
                AgentDirectory.empty().with("alice", "a", AgentKind.USER).with("bob", "b", AgentKind.USER),
                KnowledgeBase.create(), FeedbackListener.NONE);
             RawClient alice = agent(server, "alice", "a"); RawClient bob = agent(server, "bob", "b")) {
            assertThat(server.transport()).isEqualTo(transport);
            alice.send(Message.Relay.toAgent("1", "alice", "bob", "say", "over " + transport.label()));
            assertThat(alice.read()).isEqualTo(new Message.Ack("1"));
            assertThat(bob.read()).isEqualTo(Message.Relay.toAgent("1", "alice", "bob", "say", "over " + transport.label()));
            // A wrong token is refused on this transport too.
            try (RawClient mallory = new RawClient(server.port())) {
                mallory.send(new Message.Hello("h", "bob", AgentKind.USER, "not-b"));
                assertThat(mallory.read()).isInstanceOfSatisfying(Message.AuthResult.class,
                        r -> assertThat(r.accepted()).isFalse());
            }
        }
    }

    private static RawClient agent(GatewayServer server, String name, String token) throws IOException {
        RawClient c = new RawClient(server.port());
        c.send(new Message.Hello("h", name, AgentKind.USER, token));
        assertThat(c.read()).isInstanceOfSatisfying(Message.AuthResult.class, r -> assertThat(r.accepted()).isTrue());
        c.send(new Message.Register("r", List.of()));
        assertThat(c.read()).isEqualTo(new Message.Ack("r"));
        return c;
    }
}
