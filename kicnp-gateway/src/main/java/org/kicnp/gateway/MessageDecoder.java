package org.kicnp.gateway;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.channel.ChannelHandlerContext;
import io.netty.handler.codec.MessageToMessageDecoder;
import java.util.List;
import java.util.Optional;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.MessageCodec;
import org.kicnp.protocol.RelayRoute;
import org.kicnp.protocol.RelayRouteReader;

/**
 * Decodes one frame (its 4-byte length prefix still in front, as {@code LengthFieldBasedFrameDecoder} leaves it)
 * into a {@link org.kicnp.protocol.Message}, or, for a plain relay, into an {@link InboundRelay} that keeps the
 * frame so the hub can forward it without re-encoding. A payload that is not a valid message raises the codec's
 * {@link org.kicnp.protocol.ProtocolException}, which the handler answers and closes the connection on.
 * One instance per connection: it reuses a scratch array and a route reader for the relay scan (no scanner, route or
 * {@code Optional} per relay while a connection keeps writing to the same peer).
 */
final class MessageDecoder extends MessageToMessageDecoder<ByteBuf> {
    private final MessageCodec codec;
    /** Relays up to this size are scanned for forwarding; larger ones (rare) are decoded and re-encoded. */
    private static final int MAX_SCANNED = 64 * 1024;
    private byte[] scratch = new byte[512];
    private final RelayRouteReader routes = new RelayRouteReader();

    MessageDecoder(MessageCodec codec) {
        super(ByteBuf.class);
        this.codec = codec;
    }

    @Override protected void decode(ChannelHandlerContext ctx, ByteBuf frame, List<Object> out) {
        int at = frame.readerIndex() + Framing.LENGTH_BYTES;
        int length = frame.writerIndex() - at;
        if (length <= MAX_SCANNED) {
            if (length > scratch.length) {
                scratch = new byte[Math.min(MAX_SCANNED, Integer.highestOneBit(length) << 1)];
            }
            frame.getBytes(at, scratch, 0, length);
            Optional<RelayRoute> route = routes.read(scratch, 0, length);
            if (route.isPresent()) {
                out.add(new InboundRelay(route.get(), frame.retain()));
                return;
            }
        }
        out.add(codec.decode(ByteBufUtil.getBytes(frame, at, length)));
    }
}
