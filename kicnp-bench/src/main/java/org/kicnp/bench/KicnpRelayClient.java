package org.kicnp.bench;

import static java.nio.charset.StandardCharsets.US_ASCII;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.buffer.Unpooled;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelPipeline;
import io.netty.handler.codec.ByteToMessageDecoder;
import io.netty.handler.codec.CorruptedFrameException;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.MessageCodec;

/**
 * A lean K-ICNP agent for the benchmark: the real wire protocol over a real TCP connection, without the SDK's
 * thread per agent. The handshake ({@code hello}, {@code auth_result}, {@code register}, {@code ack}) goes
 * through the protocol's own {@link MessageCodec}. Each relay is the codec's encoding of
 * {@code Relay.toAgent("", me, peer, "bench", body)} — a fire-and-forget relay, as the SDK's {@code tellTo} sends,
 * which the hub does not ack (like MQTT QoS 0) — made once per agent as a template whose body digits are then
 * rewritten in place, so the client spends its CPU on the network rather than on JSON. Deliveries are recognised
 * by their type and their body read where the codec puts it (last); anything else from the hub is discarded.
 */
final class KicnpRelayClient implements RelayClient {
    static final String TOKEN_PREFIX = "bench-token-";
    private static final byte[] RELAY_PREFIX = "{\"v\":1,\"type\":\"relay\"".getBytes(US_ASCII);
    private static final int STAMP_DIGITS = 19;

    private final MessageCodec codec = new MessageCodec();
    private final int messageBytes;
    /** The length of every bench body (all agent names have the same length, so all bodies do). */
    private volatile int bodyChars;

    /** @param messageBytes bytes of each relay on the wire, the 4-byte length prefix included */
    KicnpRelayClient(int messageBytes) {
        this.messageBytes = messageBytes;
    }

    @Override public String describe() {
        return "K-ICNP relay (toAgent, fire and forget: empty id, no ack)";
    }

    @Override public RelayAgent.Encoder encoderFor(String name, String peer) {
        byte[] bare = template(name, peer, 0);
        int pad = messageBytes - bare.length;
        if (pad < 0) {
            throw new IllegalArgumentException("A relay needs at least " + bare.length + " bytes on the wire; "
                    + messageBytes + " is too few.");
        }
        byte[] frame = template(name, peer, pad);
        bodyChars = 1 + STAMP_DIGITS + pad;
        ByteBuf shared = Unpooled.wrappedBuffer(frame);
        int stampAt = indexOf(frame, "\"body\":\"t") + 9;
        return (from, stamp, buf) -> {
            int start = buf.writerIndex();
            buf.writeBytes(shared, 0, frame.length);
            Digits.put(buf, start + stampAt, stamp, STAMP_DIGITS);
        };
    }

    /** The framed relay from {@code name} to {@code peer} with {@code pad} bytes of padding in its body. */
    private byte[] template(String name, String peer, int pad) {
        String body = "t" + "0".repeat(STAMP_DIGITS) + "x".repeat(pad);
        byte[] json = codec.encode(Message.Relay.toAgent("", name, peer, "bench", body));
        byte[] frame = new byte[Framing.LENGTH_BYTES + json.length];
        frame[0] = (byte) (json.length >>> 24);
        frame[1] = (byte) (json.length >>> 16);
        frame[2] = (byte) (json.length >>> 8);
        frame[3] = (byte) json.length;
        System.arraycopy(json, 0, frame, Framing.LENGTH_BYTES, json.length);
        return frame;
    }

    private static int indexOf(byte[] haystack, String needle) {
        byte[] n = needle.getBytes(US_ASCII);
        outer:
        for (int i = 0; i + n.length <= haystack.length; i++) {
            for (int j = 0; j < n.length; j++) {
                if (haystack[i + j] != n[j]) {
                    continue outer;
                }
            }
            return i;
        }
        throw new IllegalStateException("The relay template lacks '" + needle + "'.");
    }

    @Override public void initPipeline(ChannelPipeline p, RelayAgent agent, CompletableFuture<Void> ready) {
        p.addLast(new Handler(agent, ready));
    }

    /**
     * Splits the stream into frames and handles each where it lies in the read buffer (no slice per frame, as a
     * frame decoder would make: over half of what the client allocated per message, and so most of its young
     * collections, which stall the load generator and are charged to the hub): the handshake through the codec,
     * then the fast path for deliveries.
     */
    private final class Handler extends ByteToMessageDecoder {
        private final RelayAgent agent;
        private final CompletableFuture<Void> ready;
        private int step;

        Handler(RelayAgent agent, CompletableFuture<Void> ready) {
            this.agent = agent;
            this.ready = ready;
        }

        @Override public void channelActive(ChannelHandlerContext ctx) {
            send(ctx, new Message.Hello("h", agent.name, AgentKind.USER, TOKEN_PREFIX + agent.name));
        }

        private void send(ChannelHandlerContext ctx, Message m) {
            byte[] json = codec.encode(m);
            ctx.writeAndFlush(ctx.alloc().buffer(json.length + 4).writeInt(json.length).writeBytes(json));
        }

        @Override protected void decode(ChannelHandlerContext ctx, ByteBuf in, List<Object> out) {
            while (in.readableBytes() >= Framing.LENGTH_BYTES) {
                int at = in.readerIndex();
                int length = in.getInt(at);
                if (length < 0 || length > Framing.DEFAULT_MAX_FRAME_BYTES) {
                    throw new CorruptedFrameException("Agent " + agent + " read a frame of " + length + " bytes.");
                }
                if (in.readableBytes() < Framing.LENGTH_BYTES + length) {
                    return;
                }
                int start = at + Framing.LENGTH_BYTES;
                int end = start + length;
                if (step == 2) {
                    if (isRelay(in, start, end)) {
                        agent.loop.delivered(agent, stampOf(in, start, end));
                    }
                } else {
                    handshake(ctx, codec.decode(ByteBufUtil.getBytes(in, start, length)));
                }
                in.readerIndex(end);
            }
        }

        private void handshake(ChannelHandlerContext ctx, Message m) {
            switch (m) {
                case Message.AuthResult a when a.accepted() && step == 0 -> {
                    step = 1;
                    send(ctx, new Message.Register("r", java.util.List.of()));
                }
                case Message.Ack a when step == 1 -> {
                    step = 2;
                    ready.complete(null);
                }
                case Message.Heartbeat h -> { }
                default -> ready.completeExceptionally(new IllegalStateException("Agent " + agent
                        + " got " + m + " during its handshake."));
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

    /** Whether the payload {@code buf[start, end)} is a relay. */
    private static boolean isRelay(ByteBuf buf, int start, int end) {
        if (end - start < RELAY_PREFIX.length) {
            return false;
        }
        for (int i = 0; i < RELAY_PREFIX.length; i++) {
            if (buf.getByte(start + i) != RELAY_PREFIX[i]) {
                return false;
            }
        }
        return true;
    }

    /**
     * The stamp in the body of the delivered relay {@code buf[start, end)}, its last member
     * ({@code ..."body":"t<19 digits>xxx"}}): the body's {@code bodyChars} characters end just before the closing
     * {@code "}}, so its {@code t} is found without a search (with one when a hub wrote the members otherwise).
     */
    private long stampOf(ByteBuf buf, int start, int end) {
        int expected = end - 2 - bodyChars;
        if (expected > start + 3 && buf.getByte(expected) == 't' && buf.getByte(expected - 1) == '"'
                && buf.getByte(expected - 2) == ':') {
            return Digits.get(buf, expected + 1, STAMP_DIGITS);
        }
        for (int at = start; at + BODY_MARKER.length + STAMP_DIGITS <= end; at++) {
            int k = 0;
            while (k < BODY_MARKER.length && buf.getByte(at + k) == BODY_MARKER[k]) {
                k++;
            }
            if (k == BODY_MARKER.length) {
                return Digits.get(buf, at + k, STAMP_DIGITS);
            }
        }
        throw new IllegalStateException("A delivered relay has no bench body.");
    }

    private static final byte[] BODY_MARKER = "\"body\":\"t".getBytes(US_ASCII);
}
