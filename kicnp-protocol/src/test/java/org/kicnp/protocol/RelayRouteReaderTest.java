package org.kicnp.protocol;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Optional;
import org.junit.jupiter.api.Test;

/** {@link RelayRouteReader}: one connection's relay routes, read with a scanner kept from payload to payload. */
class RelayRouteReaderTest {
    private final MessageCodec codec = new MessageCodec();
    private final RelayRouteReader reader = new RelayRouteReader();

    private Optional<RelayRoute> read(Message m) {
        byte[] payload = codec.encode(m);
        return reader.read(payload, 0, payload.length);
    }

    @Test
    void read_sameRouteAgain_givesTheSameInstance() {
        RelayRoute first = read(Message.Relay.toAgent("", "alice", "bob", "s", "one")).orElseThrow();
        RelayRoute second = read(Message.Relay.toAgent("", "alice", "bob", "other", "two")).orElseThrow();

        assertThat(first).isEqualTo(new RelayRoute("", "alice", Optional.of("bob"), Optional.empty()));
        assertThat(second).isSameAs(first);
    }

    @Test
    void read_whenAnyRoutingMemberChanges_givesTheNewRoute() {
        read(Message.Relay.toAgent("", "alice", "bob", "s", "b"));

        assertThat(read(Message.Relay.toAgent("", "alice", "carol", "s", "b")))
                .contains(new RelayRoute("", "alice", Optional.of("carol"), Optional.empty()));
        assertThat(read(Message.Relay.toAgent("r-9", "alice", "carol", "s", "b")))
                .contains(new RelayRoute("r-9", "alice", Optional.of("carol"), Optional.empty()));
        assertThat(read(Message.Relay.toAgent("r-9", "dave", "carol", "s", "b")))
                .contains(new RelayRoute("r-9", "dave", Optional.of("carol"), Optional.empty()));
        assertThat(read(Message.Relay.toKind("r-9", "dave", AgentKind.ROBOT, "s", "b")))
                .contains(new RelayRoute("r-9", "dave", Optional.empty(), Optional.of(AgentKind.ROBOT)));
        assertThat(read(Message.Relay.toKind("r-9", "dave", AgentKind.USER, "s", "b")))
                .contains(new RelayRoute("r-9", "dave", Optional.empty(), Optional.of(AgentKind.USER)));
        assertThat(read(Message.Relay.toAgent("r-9", "dave", "robot", "s", "b")))
                .contains(new RelayRoute("r-9", "dave", Optional.of("robot"), Optional.empty()));
    }

    @Test
    void read_afterAPayloadThatIsNoPlainRelay_readsTheNextOneFromScratch() {
        read(Message.Relay.toAgent("", "alice", "bob", "s", "b"));
        assertThat(read(new Message.Heartbeat(5))).isEmpty();
        byte[] broken = "{\"v\":1,\"type\":\"relay\",\"id\":\"\",\"from\":\"x\",\"toAgent\":\"y\"".getBytes(UTF_8);
        assertThat(reader.read(broken, 0, broken.length)).isEmpty();

        assertThat(read(Message.Relay.toAgent("", "alice", "bob", "s", "b")))
                .contains(new RelayRoute("", "alice", Optional.of("bob"), Optional.empty()));
    }

    @Test
    void read_honoursOffsetAndLength_andRefusesARangeOutsideThePayload() {
        byte[] json = codec.encode(Message.Relay.toAgent("", "alice", "bob", "s", "b"));
        byte[] padded = new byte[json.length + 4];
        System.arraycopy(json, 0, padded, 2, json.length);

        assertThat(reader.read(padded, 2, json.length))
                .contains(new RelayRoute("", "alice", Optional.of("bob"), Optional.empty()));
        assertThatThrownBy(() -> reader.read(json, 1, json.length)).isInstanceOf(IndexOutOfBoundsException.class);
    }
}
