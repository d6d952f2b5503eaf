package org.kicnp.gateway;

import static java.util.Objects.requireNonNull;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.MessageCodec;
import org.kicnp.protocol.RelayRoute;

/**
 * A plain relay as it arrived: its route, read without decoding its subject and body, and its whole frame (length
 * prefix included). When the relay already names its authenticated sender, the hub forwards this frame as it is —
 * the receiver gets the very bytes the sender wrote, which decode to the relay the hub would have written — and
 * otherwise decodes it in full and stamps the sender. Holds one reference to the frame: whoever consumes it
 * releases it.
 */
record InboundRelay(RelayRoute route, ByteBuf frame) {
    InboundRelay {
        requireNonNull(route, "route");
        requireNonNull(frame, "frame");
    }

    /** The relay decoded in full (for a relay that names another sender than the connection's). */
    Message.Relay decode(MessageCodec codec) {
        byte[] payload = ByteBufUtil.getBytes(frame, frame.readerIndex() + Framing.LENGTH_BYTES,
                frame.readableBytes() - Framing.LENGTH_BYTES);
        return (Message.Relay) codec.decode(payload);
    }
}
