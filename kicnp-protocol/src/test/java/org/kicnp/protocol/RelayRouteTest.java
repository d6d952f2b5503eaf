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
    void relayRoute_withMembersInAnyOrderAndWhitespace_isRead() {
        assertThat(route(" {\"body\" : \"b\" ,\n\"toAgent\":\"bob\",\"subject\":\"s\",\t\"from\":\"alice\",\"id\":\"x y\","
                + "\"type\":\"relay\",\"v\":1 } "))
                .contains(new RelayRoute("x y", "alice", Optional.of("bob"), Optional.empty()));
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"\",\"body\":\"\"}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toKind\":\"ROBOT\",\"subject\":\"s\",\"body\":\"x\"}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\","
                + "\"body\":\"\\\"q\\\" \\\\ \\/ \\b\\f\\n\\r\\t \\u00e9\\uD83D\\uDE00 \u00e9\u4e2d\ud83d\ude00\"}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"\u00e9\",\"from\":\"\u4e2d\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"}"
    })
    void relayRoute_ofAcceptedRelay_agreesWithTheFullDecoder(String json) {
        Message.Relay full = (Message.Relay) codec.decode(json.getBytes(UTF_8));
        assertThat(route(json)).contains(new RelayRoute(full.id(), full.from(), full.toAgent(), full.toKind()));
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
        // escapes in a routing member or a member name: left to the full decoder
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"al\\u0069ce\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"}",
        "{\"v\":1,\"type\":\"relay\",\"i\\u0064\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"}",
        "{\"v\":1.0,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"}",
        "{\"v\":11,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"}",
        "{\"v\":\"1\",\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"\\u12G4\"}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"tab\there\"}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":null}",
        "{\"v\":1,\"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\",}",
        "{\"v\":1 \"type\":\"relay\",\"id\":\"1\",\"from\":\"a\",\"toAgent\":\"b\",\"subject\":\"s\",\"body\":\"x\"}",
        "{}",
        "",
        "[1]"
    })
    void relayRoute_ofAnythingButAPlainRelay_isEmpty(String json) {
        assertThat(route(json)).isEmpty();
    }

    @Test
    void relayRoute_ofBrokenUtf8InTheBody_isEmpty() {
        byte[] good = codec.encode(Message.Relay.toAgent("1", "a", "b", "s", "\u00e9\u00e9"));
        byte[][] broken = {{(byte) 0xC3}, {(byte) 0xC0, (byte) 0xA9}, {(byte) 0xED, (byte) 0xA0, (byte) 0x80},
            {(byte) 0xF5, (byte) 0x80, (byte) 0x80, (byte) 0x80}, {(byte) 0xE2, (byte) 0x28, (byte) 0xA1}};
        int at = new String(good, UTF_8).indexOf('\u00e9') + 2; // the byte index of the body's second é (ASCII before)
        for (byte[] bad : broken) {
            byte[] payload = new byte[good.length - 2 + bad.length];
            System.arraycopy(good, 0, payload, 0, at);
            System.arraycopy(bad, 0, payload, at, bad.length);
            System.arraycopy(good, at + 2, payload, at + bad.length, good.length - at - 2);
            assertThat(codec.relayRoute(payload, 0, payload.length)).as("body bytes %s", java.util.Arrays.toString(bad))
                    .isEmpty();
        }
        assertThat(codec.relayRoute(good, 0, good.length)).isPresent();
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
