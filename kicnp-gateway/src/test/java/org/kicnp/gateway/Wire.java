package org.kicnp.gateway;

import static java.nio.charset.StandardCharsets.UTF_8;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.buffer.Unpooled;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.embedded.EmbeddedChannel;
import java.util.ArrayList;
import java.util.List;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.MessageCodec;

/** Frames in and out of an {@link EmbeddedChannel} running the gateway's pipeline: no sockets. */
final class Wire {
    static final MessageCodec CODEC = new MessageCodec();

    private Wire() {
    }

    /** A channel with the real pipeline over a fresh server agent. */
    static EmbeddedChannel channel(GatewayConfig config, AgentDirectory agents, KnowledgeBase kb,
                                   FeedbackListener feedback, GatewayMetrics metrics, ServerAgent[] serverOut) {
        ServerAgent server = ServerAgent.create(config, agents, kb, feedback, Retraction.removeFrom(kb), Reasoning.NONE,
                metrics);
        kb.addListener(server.knowledge());
        serverOut[0] = server;
        return channel(config, server, metrics);
    }

    /** Another connection to the same server agent (with the real pipeline). */
    static EmbeddedChannel channel(GatewayConfig config, ServerAgent server, GatewayMetrics metrics) {
        GatewayInitializer init = new GatewayInitializer(config, server, metrics,
                new io.netty.channel.group.DefaultChannelGroup(io.netty.util.concurrent.GlobalEventExecutor.INSTANCE));
        return new EmbeddedChannel(new ChannelInitializer<EmbeddedChannel>() {
            @Override protected void initChannel(EmbeddedChannel ch) {
                init.configure(ch);
            }
        });
    }

    static ByteBuf frame(Message m) {
        return frame(CODEC.encode(m));
    }

    static ByteBuf frame(String json) {
        return frame(json.getBytes(UTF_8));
    }

    static ByteBuf frame(byte[] payload) {
        ByteBuf b = Unpooled.buffer(4 + payload.length);
        b.writeInt(payload.length);
        b.writeBytes(payload);
        return b;
    }

    /** Every message the channel wrote so far, decoded (each written buffer holds whole frames, one or more). */
    static List<Message> written(EmbeddedChannel ch) {
        ch.runPendingTasks(); // the gateway writes from its event loop's tasks (a session's outbox is drained there)
        List<Message> out = new ArrayList<>();
        for (ByteBuf b = ch.readOutbound(); b != null; b = ch.readOutbound()) {
            try {
                while (b.isReadable()) { // a buffer holds one or more whole frames (the outbox writes a batch)
                    int length = b.readInt();
                    if (length > b.readableBytes()) {
                        throw new AssertionError("Length prefix " + length + " but " + b.readableBytes()
                                + " bytes follow.");
                    }
                    out.add(CODEC.decode(ByteBufUtil.getBytes(b.readSlice(length))));
                }
            } finally {
                b.release();
            }
        }
        return out;
    }
}
