package org.kicnp.gateway;

import static java.util.Objects.requireNonNull;

import io.netty.bootstrap.ServerBootstrap;
import io.netty.channel.Channel;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.MultiThreadIoEventLoopGroup;
import io.netty.channel.WriteBufferWaterMark;
import io.netty.channel.group.ChannelGroup;
import io.netty.channel.group.DefaultChannelGroup;
import io.netty.handler.ssl.SslContext;
import io.netty.util.concurrent.GlobalEventExecutor;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.kicnp.core.KnowledgeBase;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The running gateway: binds, accepts agents, and gives the platform its {@link ActionSink}. Start with
 * {@link #start}; {@link #close} stops accepting, closes every connection (failing in-flight commands) and
 * releases the threads.
 *
 * <p>Threads: each connection's messages are handled on its Netty event loop, knowledge-base calls included (they
 * are short, and the knowledge base has its own lock). Knowledge-base listeners registered by others (such as the
 * inference engine) therefore run on a gateway thread when an agent's change commits; a slow listener should hand
 * its work to its own thread. {@link FeedbackListener} calls come from the robot connection's event loop.
 */
public final class GatewayServer implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(GatewayServer.class);

    private final EventLoopGroup boss;
    private final EventLoopGroup workers;
    private final Channel listener;
    private final ChannelGroup connections;
    private final ServerAgent server;
    private final GatewayMetrics metrics;
    private final KnowledgeBase kb;
    private final Transport transport;
    private final GatewayConfig config;
    /** Further listeners ({@link #listenAlso}), closed with the gateway. */
    private final List<Channel> moreListeners = new CopyOnWriteArrayList<>();

    private GatewayServer(GatewayConfig config, EventLoopGroup boss, EventLoopGroup workers, Channel listener,
                          ChannelGroup connections, ServerAgent server, GatewayMetrics metrics, KnowledgeBase kb,
                          Transport transport) {
        this.config = config;
        this.boss = boss;
        this.workers = workers;
        this.listener = listener;
        this.connections = connections;
        this.server = server;
        this.metrics = metrics;
        this.kb = kb;
        this.transport = transport;
    }

    /**
     * Starts a gateway over a knowledge base.
     *
     * @throws GatewayException when the address cannot be bound
     */
    public static GatewayServer start(GatewayConfig config, AgentDirectory agents, KnowledgeBase kb,
                                      FeedbackListener feedback) {
        return start(config, agents, kb, feedback, Retraction.removeFrom(requireNonNull(kb, "kb")));
    }

    /**
     * Starts a gateway over a knowledge base that takes an agent's runtime frames away through {@code retraction}
     * when the agent leaves (the platform retracts them through its inference engine).
     *
     * @throws GatewayException when the address cannot be bound, or the configured transport does not work here
     */
    public static GatewayServer start(GatewayConfig config, AgentDirectory agents, KnowledgeBase kb,
                                      FeedbackListener feedback, Retraction retraction) {
        return start(config, agents, kb, feedback, retraction, Reasoning.NONE);
    }

    /**
     * Starts a gateway over a knowledge base whose agents may also ask an inference engine to prove and explain
     * ({@code prove}, {@code why}) through {@code reasoning}.
     *
     * @throws GatewayException when the address cannot be bound, or the configured transport does not work here
     */
    public static GatewayServer start(GatewayConfig config, AgentDirectory agents, KnowledgeBase kb,
                                      FeedbackListener feedback, Retraction retraction, Reasoning reasoning) {
        requireNonNull(config, "config");
        Transport transport = config.transport();
        try {
            transport.requireAvailable();
        } catch (IllegalArgumentException e) {
            throw new GatewayException(e.getMessage(), e);
        }
        GatewayMetrics metrics = new GatewayMetrics();
        ServerAgent server = ServerAgent.create(config, requireNonNull(agents, "agents"), requireNonNull(kb, "kb"),
                requireNonNull(feedback, "feedback"), requireNonNull(retraction, "retraction"),
                requireNonNull(reasoning, "reasoning"), metrics);
        ChannelGroup connections = new DefaultChannelGroup("kicnp-agents", GlobalEventExecutor.INSTANCE);
        EventLoopGroup boss = new MultiThreadIoEventLoopGroup(1, transport.ioHandlerFactory());
        EventLoopGroup workers = new MultiThreadIoEventLoopGroup(config.ioThreads(), transport.ioHandlerFactory());
        try {
            Channel ch = bind(config, boss, workers, server, metrics, connections);
            kb.addListener(server.knowledge());
            GatewayServer gw = new GatewayServer(config, boss, workers, ch, connections, server, metrics, kb,
                    transport);
            LOG.info("K-ICNP gateway '{}' listening on {}{} ({} transport).", config.serverName(), ch.localAddress(),
                    config.tls().isPresent() ? " (TLS)" : "", transport.label());
            return gw;
        } catch (Exception e) {
            boss.shutdownGracefully(0, 1, TimeUnit.SECONDS);
            workers.shutdownGracefully(0, 1, TimeUnit.SECONDS);
            if (e instanceof InterruptedException) {
                Thread.currentThread().interrupt();
            }
            throw new GatewayException("Cannot listen on " + config.host() + ":" + config.port() + ": " + e.getMessage(), e);
        }
    }

    private static Channel bind(GatewayConfig config, EventLoopGroup boss, EventLoopGroup workers, ServerAgent server,
                                GatewayMetrics metrics, ChannelGroup connections) throws InterruptedException {
        return new ServerBootstrap()
                .group(boss, workers)
                .channel(config.transport().serverChannel())
                .childOption(ChannelOption.TCP_NODELAY, true)
                .childOption(ChannelOption.WRITE_BUFFER_WATER_MARK,
                        new WriteBufferWaterMark(config.writeLowWaterBytes(), config.writeHighWaterBytes()))
                .childHandler(new GatewayInitializer(config, server, metrics, connections))
                .bind(config.host(), config.port()).sync().channel();
    }

    /**
     * Also listens on {@code host:port}, for agents on other machines: the same server agent behind it (the same
     * agents, tokens, knowledge and relays as the first address), with {@code tls} on this address alone, or in
     * plain TCP when it is empty. The platform keeps its first address on loopback for its own agents and tools.
     *
     * @return the address bound (with the actual port when {@code port} is 0)
     * @throws GatewayException when the address cannot be bound
     */
    public InetSocketAddress listenAlso(String host, int port, Optional<SslContext> tls) {
        requireNonNull(host, "host");
        requireNonNull(tls, "tls");
        GatewayConfig c = config.withHost(host).withPort(port).withTls(tls);
        try {
            Channel ch = bind(c, boss, workers, server, metrics, connections);
            moreListeners.add(ch);
            LOG.info("K-ICNP gateway '{}' also listening on {}{}.", config.serverName(), ch.localAddress(),
                    tls.isPresent() ? " (TLS)" : " (plain TCP)");
            return (InetSocketAddress) ch.localAddress();
        } catch (Exception e) {
            if (e instanceof InterruptedException) {
                Thread.currentThread().interrupt();
            }
            throw new GatewayException("Cannot listen on " + host + ":" + port + ": " + e.getMessage(), e);
        }
    }

    /** The further addresses the gateway listens on ({@link #listenAlso}), in the order they were bound. */
    public List<InetSocketAddress> moreAddresses() {
        return moreListeners.stream().map(ch -> (InetSocketAddress) ch.localAddress()).toList();
    }

    /** The address the gateway listens on (with the actual port when it was started on port 0). */
    public InetSocketAddress address() {
        return (InetSocketAddress) listener.localAddress();
    }

    public int port() {
        return address().getPort();
    }

    /** Where the platform sends commands to robots. */
    public ActionSink actionSink() {
        return server.commands();
    }

    /** The socket transport it runs on. */
    public Transport transport() {
        return transport;
    }

    public GatewayMetrics metrics() {
        return metrics;
    }

    /** The names of the registered agents, sorted. */
    public List<String> registeredAgents() {
        return server.registeredAgents();
    }

    /** Commands sent and not yet ended or failed. */
    public int commandsInFlight() {
        return server.commands().inFlightCount();
    }

    @Override public void close() {
        kb.removeListener(server.knowledge());
        listener.close().awaitUninterruptibly();
        for (Channel ch : moreListeners) {
            ch.close().awaitUninterruptibly();
        }
        server.commands().closing();
        connections.close().awaitUninterruptibly();
        boss.shutdownGracefully(0, 1, TimeUnit.SECONDS).syncUninterruptibly();
        workers.shutdownGracefully(0, 1, TimeUnit.SECONDS).syncUninterruptibly();
        LOG.info("K-ICNP gateway stopped.");
    }
}
