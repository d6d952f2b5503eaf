package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.buffer.Unpooled;
import io.netty.channel.embedded.EmbeddedChannel;
import io.netty.handler.codec.DecoderException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.ProtocolException;
import org.kicnp.protocol.RelayRoute;

/** The Netty codec alone: frames split and joined arbitrarily still decode; the encoder writes length + JSON. */
class MessageCodecChannelTest {
    /** The plain relays the frame decoder offered its sink, each with the bytes of its frame. */
    private final List<Map.Entry<RelayRoute, byte[]>> offered = new ArrayList<>();
    /** Whether the sink takes what it is offered (as the handler does when the relay names its agent). */
    private boolean taking = true;

    private EmbeddedChannel codec() {
        // As in the gateway's pipeline: the frame decoder leaves the length prefix in front of each frame.
        FrameDecoder.RelaySink sink = (route, buffer, index, length) -> {
            offered.add(Map.entry(route, ByteBufUtil.getBytes(buffer, index, length)));
            return taking;
        };
        return new EmbeddedChannel(new FrameDecoder(1 << 20, sink), new MessageDecoder(Wire.CODEC),
                new MessageEncoder(Wire.CODEC));
    }

    @Test
    void decoder_reassemblesFramesSplitAcrossReads() {
        EmbeddedChannel ch = codec();
        ByteBuf two = Unpooled.wrappedBuffer(Wire.frame(new Message.Ack("1")), Wire.frame(new Message.Heartbeat(7)));
        while (two.isReadable()) {
            ch.writeInbound(two.readRetainedSlice(Math.min(3, two.readableBytes())));
        }
        two.release();
        assertThat(List.<Object>of(ch.readInbound(), ch.readInbound()))
                .containsExactly(new Message.Ack("1"), new Message.Heartbeat(7));
        assertThat(ch.finish()).isFalse();
    }

    @Test
    void frameDecoder_offersAPlainRelayWithItsRouteAndWholeFrame_andAnyOtherRelayIsDecoded() {
        EmbeddedChannel ch = codec();
        Message.Relay plain = Message.Relay.toAgent("7", "alice", "bob", "say", "hi");
        ByteBuf frame = Wire.frame(plain);
        byte[] bytes = ByteBufUtil.getBytes(frame);
        ch.writeInbound(frame);
        assertThat((Object) ch.readInbound()).as("taken by the sink: nothing goes on").isNull();
        assertThat(offered).hasSize(1);
        assertThat(offered.getFirst().getKey()).isEqualTo(new RelayRoute("7", "alice", Optional.of("bob"),
                Optional.empty()));
        assertThat(offered.getFirst().getValue()).isEqualTo(bytes);

        ch.writeInbound(Wire.frame("{\"v\":1,\"type\":\"relay\",\"id\":\"8\",\"from\":\"alice\",\"toAgent\":\"bob\","
                + "\"subject\":\"s\",\"body\":\"b\",\"extra\":true}"));
        assertThat((Object) ch.readInbound()).isEqualTo(Message.Relay.toAgent("8", "alice", "bob", "s", "b"));
        assertThat(offered).as("not a plain relay: never offered").hasSize(1);
        assertThat(ch.finish()).isFalse();
    }

    @Test
    void plainRelayTheSinkDeclines_isDecoded() {
        taking = false;
        EmbeddedChannel ch = codec();
        Message.Relay plain = Message.Relay.toAgent("9", "carol", "bob", "say", "hi");
        ch.writeInbound(Wire.frame(plain));
        assertThat(offered).hasSize(1);
        assertThat((Object) ch.readInbound()).isEqualTo(plain);
        assertThat(ch.finish()).isFalse();
    }

    @Test
    void encoder_writesLengthPrefixThenJson() {
        EmbeddedChannel ch = codec();
        Message m = new Message.AuthResult("1", true, "kicnp", Optional.empty());
        ch.writeOutbound(m);
        ByteBuf out = ch.readOutbound();
        byte[] json = Wire.CODEC.encode(m);
        assertThat(out.readInt()).isEqualTo(json.length);
        assertThat(io.netty.buffer.ByteBufUtil.getBytes(out)).isEqualTo(json);
        out.release();
    }

    @Test
    void decoder_whenPayloadInvalid_raisesProtocolExceptionWithCode() {
        EmbeddedChannel ch = codec();
        assertThatThrownBy(() -> ch.writeInbound(Wire.frame("{\"v\":1,\"type\":\"hello\",\"id\":\"1\",\"agent\":\"x\","
                + "\"kind\":\"" + AgentKind.USER.name().toLowerCase() + "\"}")))
                .isInstanceOf(DecoderException.class)
                .cause().isInstanceOfSatisfying(ProtocolException.class,
                        e -> assertThat(e.code()).isEqualTo(ErrorCode.BAD_MESSAGE))
                .hasMessage("A 'hello' message needs the member 'token'.");
    }
}
