package org.kicnp.protocol;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** {@link MessageCodec#relayRoute}: the hub's routing read of a relay, and what it leaves to the full decoder. */
class RelayRouteTest {
    private final MessageCodec codec = new MessageCodec();

    private Optional<RelayRoute> route(String json) {
        byte[] bytes = ("xx" + json + "yy").getBytes(UTF_8); // offset and length are honoured
        return codec.relayRoute(bytes, 2, bytes.length - 4);
    }

    @Test
    void relayRoute_ofEncodedRelayToAgent_givesItsIdSenderAndReceiver() {
        byte[] payload = codec.encode(Message.Relay.toAgent("r-1", "alice", "bob", "say", "h\u00e9llo \"you\"\n"));
        assertThat(codec.relayRoute(payload, 0, payload.length))
                .contains(new RelayRoute("r-1", "alice", Optional.of("bob"), Optional.empty()));
    }

    @Test
    void relayRoute_ofEncodedRelayToKind_givesTheKind() {
        byte[] payload = codec.encode(Message.Relay.toKind("r-2", "alice", AgentKind.ROBOT, "stop", "now"));
        assertThat(codec.relayRoute(payload, 0, payload.length))
                .contains(new RelayRoute("r-2", "alice", Optional.empty(), Optional.of(AgentKind.ROBOT)));
    }

    @Test
    void relayRoute_withMembersInAnyOrderAndEscapedId_isRead() {
        assertThat(route("{\"body\":\"b\",\"toAgent\":\"bob\",\"subject\":\"s\",\"from\":\"al\\u0069ce\",\"id\":\"a\\\"b\","
                + "\"type\":\"relay\",\"v\":1}"))
                .contains(new RelayRoute("a\"b", "alice", Optional.of("bob"), Optional.empty()));
    }

    @ParameterizedTest
    @ValueSource(strings = {
        // an unknown member: the full decoder ignores it, but the bytes must not be forwarded with it
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\",\"z\":1}",
        // a repeated member: a receiver might read the other one
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"eve\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"}",
        "{\"v\":2,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"}",
        "{\"v\":1,\"type\":\"query\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\"}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"toKind\":\"robot\",\"subject\":\"s\",\"body\":\"x\"}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toKind\":\"martian\",\"subject\":\"s\",\"body\":\"x\"}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":7}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"} {}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"\\q\"}",
        "[1]"
    })
    void relayRoute_ofAnythingButAPlainRelay_isEmpty(String json) {
        assertThat(route(json)).isEmpty();
    }

    @Test
    void encode_ofAck_givesTheGeneratorsBytesWithAndWithoutEscapes() {
        assertThat(new String(codec.encode(new Message.Ack("r-17")), UTF_8))
                .isEqualTo("{\"v\":1,\"type\":\"ack\",\"id\":\"r-17\"}");
        assertThat(new String(codec.encode(new Message.Ack("a\"b\u00e9")), UTF_8))
                .isEqualTo("{\"v\":1,\"type\":\"ack\",\"id\":\"a\\\"b\u00e9\"}");
        assertThat(codec.decode(codec.encode(new Message.Ack("a\\b\n")))).isEqualTo(new Message.Ack("a\\b\n"));
    }
}
