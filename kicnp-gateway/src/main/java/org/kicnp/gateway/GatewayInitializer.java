package org.kicnp.gateway;

import io.netty.channel.Channel;
import io.netty.channel.ChannelInitializer;
import io.netty.channel.ChannelPipeline;
import io.netty.channel.group.ChannelGroup;
import io.netty.channel.socket.SocketChannel;
import io.netty.handler.timeout.IdleStateHandler;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import org.kicnp.protocol.MessageCodec;

/**
 * Builds each connection's pipeline: optional TLS, the bounded length-prefix decoder, the JSON message decoder and
 * encoder, the heartbeat timer, and the connection's {@link GatewayHandler}.
 */
final class GatewayInitializer extends ChannelInitializer<SocketChannel> {
    private final GatewayConfig config;
    private final ServerAgent server;
    private final GatewayMetrics metrics;
    private final MessageCodec codec = new MessageCodec();

    private final ChannelGroup connections;

    GatewayInitializer(GatewayConfig config, ServerAgent server, GatewayMetrics metrics, ChannelGroup connections) {
        this.connections = connections;
        this.config = config;
        this.server = server;
        this.metrics = metrics;
    }

    @Override protected void initChannel(SocketChannel ch) {
        connections.add(ch);
        configure(ch);
    }

    /** Installs the handlers on a channel; also used on {@code EmbeddedChannel}s in tests. */
    void configure(Channel ch) {
        ChannelPipeline p = ch.pipeline();
        config.tls().ifPresent(tls -> p.addLast("tls", tls.newHandler(ch.alloc())));
        // Reader idleness only, of the bytes read (a relay the frame decoder forwards reaches no handler after it).
        // A writer-idle check here would wrap every write in a promise with a listener; the handler sends
        // heartbeats itself when the connection has been written nothing for a third of the timeout.
        long timeout = config.heartbeatTimeout().toMillis();
        p.addLast("idle", new IdleStateHandler(timeout, 0, 0, TimeUnit.MILLISECONDS));
        GatewayHandler agent = new GatewayHandler(server, metrics, codec, Duration.ofMillis(Math.max(10, timeout / 3)),
                config.maxFrameBytes(), config.clock());
        p.addLast("frames", new FrameDecoder(config.maxFrameBytes(), agent)); // the prefix stays in each frame
        p.addLast("decoder", new MessageDecoder(codec));
        p.addLast("encoder", new MessageEncoder(codec, config.maxFrameBytes()));
        p.addLast("agent", agent);
    }
}
