package org.kicnp.gateway;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.channel.ChannelHandlerContext;
import io.netty.handler.codec.MessageToMessageDecoder;
import java.util.List;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.MessageCodec;

/**
 * Decodes one frame (its 4-byte length prefix still in front, as {@link FrameDecoder} leaves it) into a
 * {@link org.kicnp.protocol.Message}: every frame the frame decoder did not forward itself as a plain relay (any other
 * message, and a relay whose sender is not authenticated yet or that names another sender, which the handler then
 * stamps with the authenticated one). A payload that is not a valid message raises the codec's
 * {@link org.kicnp.protocol.ProtocolException}, which the handler answers and closes the connection on.
 */
final class MessageDecoder extends MessageToMessageDecoder<ByteBuf> {
    private final MessageCodec codec;

    MessageDecoder(MessageCodec codec) {
        super(ByteBuf.class);
        this.codec = codec;
    }

    @Override protected void decode(ChannelHandlerContext ctx, ByteBuf frame, List<Object> out) {
        int at = frame.readerIndex() + Framing.LENGTH_BYTES;
        out.add(codec.decode(ByteBufUtil.getBytes(frame, at, frame.writerIndex() - at)));
    }
}
