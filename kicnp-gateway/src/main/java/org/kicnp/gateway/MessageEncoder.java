package org.kicnp.gateway;

import io.netty.buffer.ByteBuf;
import io.netty.channel.ChannelHandlerContext;
import io.netty.handler.codec.MessageToByteEncoder;
import java.util.Optional;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.MessageCodec;

/**
 * Encodes a {@link Message} as one frame: the 4-byte big-endian length, then the JSON payload. An answer longer than
 * the frame limit (a pull of a large subtree, a query of a large class) would make the agent, whose limit is the
 * same by default, drop the connection without learning why; it is answered with an error saying so instead.
 */
final class MessageEncoder extends MessageToByteEncoder<Message> {
    private final MessageCodec codec;
    private final int maxFrameBytes;

    MessageEncoder(MessageCodec codec) {
        this(codec, Framing.DEFAULT_MAX_FRAME_BYTES);
    }

    MessageEncoder(MessageCodec codec, int maxFrameBytes) {
        super(Message.class);
        this.codec = codec;
        this.maxFrameBytes = maxFrameBytes;
    }

    @Override protected void encode(ChannelHandlerContext ctx, Message message, ByteBuf out) {
        byte[] payload = payload(codec, message, maxFrameBytes);
        out.writeInt(payload.length);
        out.writeBytes(payload);
    }

    /** The payload of a message, or of the error that replaces an answer longer than {@code maxFrameBytes}. */
    static byte[] payload(MessageCodec codec, Message message, int maxFrameBytes) {
        byte[] payload = codec.encode(message);
        Optional<String> id = payload.length > maxFrameBytes ? answerId(message) : Optional.empty();
        if (id.isEmpty()) {
            return payload;
        }
        return codec.encode(Message.ErrorReply.to(id.get(), ErrorCode.REJECTED, "The answer is " + payload.length
                + " bytes, more than one message may carry (" + maxFrameBytes + " bytes); ask for less, such as a "
                + "smaller subtree or class."));
    }

    /** The request a potentially long answer answers; other messages are bounded by what the server was sent. */
    private static Optional<String> answerId(Message m) {
        return switch (m) {
            case Message.Frames f -> Optional.of(f.id());
            case Message.Proofs p -> Optional.of(p.id());
            case Message.Explained x -> Optional.of(x.id());
            case Message.NotFired x -> Optional.of(x.id());
            case Message.Answer a -> Optional.of(a.id());
            default -> Optional.empty();
        };
    }
}
