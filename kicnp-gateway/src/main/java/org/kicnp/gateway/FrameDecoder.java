package org.kicnp.gateway;

import io.netty.buffer.ByteBuf;
import io.netty.channel.ChannelHandlerContext;
import io.netty.handler.codec.LengthFieldBasedFrameDecoder;
import java.util.Optional;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.RelayRoute;
import org.kicnp.protocol.RelayRouteReader;

/**
 * A connection's length-prefix decoder (bounded, failing fast on an oversize length, the prefix kept in each frame),
 * which hands a plain relay to the connection's {@link RelaySink} where it lies in the read buffer, instead of cutting
 * a frame off for the decoders after it. The sink forwards it when it names the connection's agent as its sender
 * (what every well-behaved agent writes): no slice, no decoded object, nothing queued between the sender's read and
 * the receiver's write buffer, so the relay hot path makes no garbage, and a busy hub collects less often (each young
 * collection stalls every relay in flight). Every other frame, a relay the sink declines included, goes on to
 * {@link MessageDecoder} as before.
 *
 * <p>Order is kept: the decoder takes one frame per call, and Netty passes on what a call produced before it makes
 * the next, so a relay handled here comes after every message read before it.
 */
final class FrameDecoder extends LengthFieldBasedFrameDecoder {
    /** Relays up to this size are scanned here; larger ones (rare) take the general path. */
    private static final int MAX_SCANNED = 64 * 1024;

    /** Takes plain relays as they lie in the read buffer. */
    interface RelaySink {
        /**
         * Forwards the plain relay with route {@code route} whose frame is the {@code length} bytes of {@code buffer}
         * from {@code index} (prefix included; read them, keep no reference, move no index), or declines it.
         *
         * @return whether it was taken; when not, the frame goes on to be decoded in full
         */
        boolean relayNow(RelayRoute route, ByteBuf buffer, int index, int length);
    }

    private final RelaySink sink;
    private final RelayRouteReader routes = new RelayRouteReader();
    private byte[] scratch = new byte[512];

    /** @param maxFrameBytes the longest payload accepted (the length prefix not counted) */
    FrameDecoder(int maxFrameBytes, RelaySink sink) {
        // failFast: an oversize length is refused when read, without waiting for (or buffering) its bytes.
        super(maxFrameBytes + Framing.LENGTH_BYTES, 0, Framing.LENGTH_BYTES, 0, 0, true);
        this.sink = sink;
    }

    /**
     * The frame at {@code index} for the next decoder, or null when the sink took it as a plain relay (the caller
     * moves past it either way).
     */
    @Override protected ByteBuf extractFrame(ChannelHandlerContext ctx, ByteBuf buffer, int index, int length) {
        int payload = length - Framing.LENGTH_BYTES;
        if (payload <= MAX_SCANNED) {
            if (payload > scratch.length) {
                scratch = new byte[Math.min(MAX_SCANNED, Integer.highestOneBit(payload) << 1)];
            }
            buffer.getBytes(index + Framing.LENGTH_BYTES, scratch, 0, payload);
            Optional<RelayRoute> route = routes.read(scratch, 0, payload);
            if (route.isPresent() && sink.relayNow(route.get(), buffer, index, length)) {
                return null;
            }
        }
        return super.extractFrame(ctx, buffer, index, length);
    }
}
