package org.kicnp.bench;

import static java.nio.charset.StandardCharsets.US_ASCII;

import io.netty.buffer.ByteBuf;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelPipeline;
import io.netty.handler.codec.ByteToMessageDecoder;
import io.netty.handler.codec.CorruptedFrameException;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * A minimal MQTT 3.1.1 client, QoS 0 only, over Netty: {@code CONNECT} (clean session, no keep-alive), then
 * {@code SUBSCRIBE} to the agent's own topic (its name), then {@code PUBLISH} to the peer's topic. Hand-written
 * rather than Eclipse Paho because Paho gives every client three threads of its own and a blocking publish; 1,000
 * Paho clients would be 3,000 threads on a 2-core machine, so the client, not the broker, would be measured. This
 * client and {@link KicnpRelayClient} share the same event loops and batching, so both hubs face the same load.
 */
final class MqttRelayClient implements RelayClient {
    private static final int STAMP_DIGITS = 19;
    private static final int CONNACK = 2;
    private static final int PUBLISH = 3;
    private static final int SUBACK = 9;

    private final int messageBytes;

    /** @param messageBytes bytes of each PUBLISH packet on the wire, fixed header included */
    MqttRelayClient(int messageBytes) {
        this.messageBytes = messageBytes;
    }

    @Override public String describe() {
        return "MQTT 3.1.1 QoS 0 publish to the peer's topic (no acks)";
    }

    @Override public RelayAgent.Encoder encoderFor(String name, String peer) {
        byte[] topic = peer.getBytes(US_ASCII);
        int remainingGuess = messageBytes - 1 - varintSize(messageBytes);
        int remaining = messageBytes - 1 - varintSize(remainingGuess);
        int payload = remaining - 2 - topic.length;
        if (payload < 1 + STAMP_DIGITS) {
            throw new IllegalArgumentException("A PUBLISH to '" + peer + "' needs more than " + messageBytes + " bytes.");
        }
        return (from, stamp, buf) -> {
            buf.ensureWritable(messageBytes); // the stamp's digits are set in place, past the writer index
            buf.writeByte(PUBLISH << 4);
            writeVarint(buf, remaining);
            buf.writeShort(topic.length).writeBytes(topic);
            buf.writeByte('t');
            int at = buf.writerIndex();
            buf.writerIndex(at + STAMP_DIGITS);
            Digits.put(buf, at, stamp, STAMP_DIGITS);
            buf.writeZero(payload - 1 - STAMP_DIGITS);
        };
    }

    @Override public void initPipeline(ChannelPipeline p, RelayAgent agent, CompletableFuture<Void> ready) {
        p.addLast(new Handler(agent, ready));
    }

    private static int varintSize(int value) {
        return value < 128 ? 1 : value < 16_384 ? 2 : value < 2_097_152 ? 3 : 4;
    }

    private static void writeVarint(ByteBuf buf, int value) {
        int v = value;
        do {
            int b = v % 128;
            v /= 128;
            buf.writeByte(v > 0 ? b | 0x80 : b);
        } while (v > 0);
    }

    private static ByteBuf connect(ChannelHandlerContext ctx, String clientId) {
        byte[] id = clientId.getBytes(US_ASCII);
        ByteBuf buf = ctx.alloc().buffer();
        buf.writeByte(0x10);
        writeVarint(buf, 10 + 2 + id.length);
        buf.writeShort(4).writeBytes("MQTT".getBytes(US_ASCII)).writeByte(4) // protocol name and level 4 (3.1.1)
                .writeByte(0x02) // clean session
                .writeShort(0) // keep-alive off: the bench runs are shorter than any sensible keep-alive
                .writeShort(id.length).writeBytes(id);
        return buf;
    }

    private static ByteBuf subscribe(ChannelHandlerContext ctx, String topic) {
        byte[] t = topic.getBytes(US_ASCII);
        ByteBuf buf = ctx.alloc().buffer();
        buf.writeByte(0x82);
        writeVarint(buf, 2 + 2 + t.length + 1);
        buf.writeShort(1).writeShort(t.length).writeBytes(t).writeByte(0); // packet id 1, QoS 0
        return buf;
    }

    /**
     * Splits the stream into whole MQTT packets (fixed header, remaining length, body) and handles each where it lies
     * in the read buffer, without a slice per packet (as {@link KicnpRelayClient} reads its frames: the clients cost
     * the two hubs alike).
     */
    private static final class Handler extends ByteToMessageDecoder {
        private final RelayAgent agent;
        private final CompletableFuture<Void> ready;

        Handler(RelayAgent agent, CompletableFuture<Void> ready) {
            this.agent = agent;
            this.ready = ready;
        }

        @Override protected void decode(ChannelHandlerContext ctx, ByteBuf in, List<Object> out) {
            while (true) {
                int start = in.readerIndex();
                int avail = in.readableBytes();
                int length = 0;
                int multiplier = 1;
                int i = 1;
                while (true) {
                    if (i >= avail) {
                        return;
                    }
                    int b = in.getByte(start + i);
                    length += (b & 0x7F) * multiplier;
                    multiplier *= 128;
                    i++;
                    if ((b & 0x80) == 0) {
                        break;
                    }
                    if (i > 4) {
                        throw new CorruptedFrameException("An MQTT remaining length is longer than 4 bytes.");
                    }
                }
                if (avail < i + length) {
                    return;
                }
                packet(ctx, in, start, i);
                in.readerIndex(start + i + length);
            }
        }

        @Override public void channelActive(ChannelHandlerContext ctx) {
            ctx.writeAndFlush(connect(ctx, agent.name));
        }

        /** The packet at {@code at} in {@code p}, whose fixed header is {@code header} bytes long. */
        private void packet(ChannelHandlerContext ctx, ByteBuf p, int at, int header) {
            int type = (p.getByte(at) & 0xFF) >>> 4;
            switch (type) {
                case PUBLISH -> {
                    int topicLength = p.getUnsignedShort(at + header);
                    int payload = at + header + 2 + topicLength; // QoS 0: no packet id
                    agent.loop.delivered(agent, Digits.get(p, payload + 1, STAMP_DIGITS));
                }
                case CONNACK -> {
                    if (p.getByte(at + header + 1) != 0) {
                        ready.completeExceptionally(new IllegalStateException("The broker refused " + agent
                                + " with CONNACK code " + p.getByte(at + header + 1) + "."));
                    } else {
                        ctx.writeAndFlush(subscribe(ctx, agent.name));
                    }
                }
                case SUBACK -> ready.complete(null);
                default -> { }
            }
        }

        @Override public void channelReadComplete(ChannelHandlerContext ctx) throws Exception {
            super.channelReadComplete(ctx);
            agent.loop.readComplete();
        }

        @Override public void channelInactive(ChannelHandlerContext ctx) throws Exception {
            super.channelInactive(ctx);
            if (ready.isDone() && !agent.loop.closing) {
                org.slf4j.LoggerFactory.getLogger(RelayDriver.class).warn("Bench agent {}'s connection closed.", agent);
            }
            ready.completeExceptionally(new IllegalStateException("Agent " + agent + "'s connection closed."));
        }

        @Override public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
            if (ready.isDone()) {
                org.slf4j.LoggerFactory.getLogger(RelayDriver.class).warn("Bench agent {} failed; closing it.", agent, cause);
            }
            ready.completeExceptionally(cause);
            ctx.close();
        }
    }
}
