package org.kicnp.gateway;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.channel.ChannelHandlerContext;
import io.netty.handler.codec.MessageToMessageDecoder;
import java.util.List;
import org.kicnp.protocol.MessageCodec;

/**
 * Decodes the payload of one frame (the length prefix already stripped by {@code LengthFieldBasedFrameDecoder})
 * into a {@link org.kicnp.protocol.Message}. A payload that is not a valid message raises the codec's
 * {@link org.kicnp.protocol.ProtocolException}, which the handler answers and closes the connection on.
 */
final class MessageDecoder extends MessageToMessageDecoder<ByteBuf> {
    private final MessageCodec codec;

    MessageDecoder(MessageCodec codec) {
        super(ByteBuf.class);
        this.codec = codec;
    }

    @Override protected void decode(ChannelHandlerContext ctx, ByteBuf frame, List<Object> out) {
        out.add(codec.decode(ByteBufUtil.getBytes(frame)));
    }
}
