package org.kicnp.gateway;

import io.netty.buffer.ByteBuf;
import io.netty.channel.ChannelHandlerContext;
import io.netty.handler.codec.MessageToByteEncoder;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.MessageCodec;

/** Encodes a {@link Message} as one frame: the 4-byte big-endian length, then the JSON payload. */
final class MessageEncoder extends MessageToByteEncoder<Message> {
    private final MessageCodec codec;

    MessageEncoder(MessageCodec codec) {
        super(Message.class);
        this.codec = codec;
    }

    @Override protected void encode(ChannelHandlerContext ctx, Message message, ByteBuf out) {
        byte[] payload = codec.encode(message);
        out.writeInt(payload.length);
        out.writeBytes(payload);
    }
}
