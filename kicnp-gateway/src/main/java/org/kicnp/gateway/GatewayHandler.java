package org.kicnp.gateway;

import io.netty.buffer.ByteBuf;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import io.netty.handler.codec.CorruptedFrameException;
import io.netty.handler.codec.DecoderException;
import io.netty.handler.codec.TooLongFrameException;
import io.netty.handler.timeout.IdleState;
import io.netty.handler.timeout.IdleStateEvent;
import java.io.IOException;
import java.time.Duration;
import java.time.InstantSource;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.ErrorReply;
import org.kicnp.protocol.MessageCodec;
import org.kicnp.protocol.ProtocolException;
import org.kicnp.protocol.RelayRoute;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One agent connection: enforces "authenticate first", dispatches each message over the closed set, answers
 * protocol errors and closes that connection only, keeps heartbeats, and cleans up when the connection closes.
 * Reads decoded {@link Message}s, and forwards the plain relays its connection's {@link FrameDecoder} hands it where
 * they lie in the read buffer.
 */
final class GatewayHandler extends ChannelInboundHandlerAdapter implements FrameDecoder.RelaySink {
    private static final Logger LOG = LoggerFactory.getLogger(GatewayHandler.class);
    private static final Pattern NETTY_TOO_LONG = Pattern.compile("exceeds (\\d+): (\\d+)");

    private final ServerAgent server;
    private final GatewayMetrics metrics;
    private final MessageCodec codec;
    private final long heartbeatNanos;
    private final int maxFrameBytes;
    /** The wall clock of a heartbeat's time ({@link GatewayConfig#clock}). */
    private final InstantSource clock;
    private Session session;
    private ScheduledFuture<?> heartbeats;

    /**
     * @param heartbeatEvery how long the server may send nothing before it sends a heartbeat
     * @param maxFrameBytes the longest answer sent as it is (the server's frame limit)
     */
    GatewayHandler(ServerAgent server, GatewayMetrics metrics, MessageCodec codec, Duration heartbeatEvery,
            int maxFrameBytes, InstantSource clock) {
        this.maxFrameBytes = maxFrameBytes;
        this.clock = clock;
        this.server = server;
        this.metrics = metrics;
        this.codec = codec;
        this.heartbeatNanos = heartbeatEvery.toNanos();
    }

    @Override public void handlerAdded(ChannelHandlerContext ctx) {
        session = new Session(ctx.channel(), codec, maxFrameBytes);
        metrics.connections.incrementAndGet();
    }

    /**
     * Starts the heartbeat check. It looks at the time of the session's last write rather than wrapping every write
     * to watch it (as a writer-idle {@code IdleStateHandler} does, at the cost of a promise and a listener for each
     * message relayed).
     */
    @Override public void channelActive(ChannelHandlerContext ctx) throws Exception {
        heartbeats = ctx.executor().scheduleAtFixedRate(this::heartbeatIfQuiet, heartbeatNanos, heartbeatNanos,
                TimeUnit.NANOSECONDS);
        super.channelActive(ctx);
    }

    private void heartbeatIfQuiet() {
        if (System.nanoTime() - session.lastWriteNanos() >= heartbeatNanos) {
            server.out().send(session, new Message.Heartbeat(clock.millis()));
        }
    }

    @Override public void channelInactive(ChannelHandlerContext ctx) throws Exception {
        if (heartbeats != null) {
            heartbeats.cancel(false);
        }
        server.connectionClosed(session);
        super.channelInactive(ctx);
    }

    @Override public void channelRead(ChannelHandlerContext ctx, Object msg) {
        ReadBatch.current().open();
        if (msg instanceof Message message) {
            read(message);
        } else {
            ctx.fireChannelRead(msg);
        }
    }

    /** The end of this connection's batch of reads: what the batch sent is written and flushed now. */
    @Override public void channelReadComplete(ChannelHandlerContext ctx) {
        ReadBatch.current().close();
        ctx.fireChannelReadComplete();
    }

    /**
     * Forwards a plain relay as it arrived, byte for byte, when this connection's agent is authenticated and the
     * relay names it as its sender (what every well-behaved agent writes); declines it otherwise, and the relay is
     * decoded in full, so the hub stamps the sender it authenticated ({@link ServerAgent#relay}).
     */
    @Override public boolean relayNow(RelayRoute route, ByteBuf buffer, int index, int length) {
        Session.State state = session.state();
        if ((state != Session.State.AUTHENTICATED && state != Session.State.REGISTERED)
                || !route.from().equals(session.agent())) {
            return false;
        }
        ReadBatch.current().open();
        metrics.received.increment();
        server.relayFrame(session, route, buffer, index, length).ifPresent(this::reply);
        return true;
    }

    private void read(Message message) {
        metrics.received.increment();
        switch (session.state()) {
            case CLOSING -> { }
            case NEW -> {
                if (message instanceof Message.Hello hello) {
                    server.authenticate(session, hello);
                } else {
                    String text = "Send 'hello' first: '" + org.kicnp.protocol.MessageType.of(message).wireName()
                            + "' before authentication.";
                    // The answer to a request echoes its id (none for a fire-and-forget relay's empty one).
                    refuse(message instanceof Message.Request r && !r.id().isEmpty()
                            ? ErrorReply.to(r.id(), ErrorCode.NOT_AUTHENTICATED, text)
                            : ErrorReply.of(ErrorCode.NOT_AUTHENTICATED, text));
                }
            }
            case AUTHENTICATED, REGISTERED -> dispatch(message);
        }
    }

    private void dispatch(Message message) {
        KnowledgeAccess kb = server.knowledge();
        switch (message) {
            case Message.Hello h -> refuse(ErrorReply.to(h.id(), ErrorCode.BAD_MESSAGE,
                    "This connection is already authenticated as " + session + "."));
            case Message.Register r -> server.register(session, r).ifPresent(this::reply);
            case Message.Heartbeat h -> { }
            case Message.Relay r -> server.relay(session, r).ifPresent(this::reply);
            case Message.Command c -> reply(server.commands().fromAgent(session, c));
            case Message.Feedback f -> server.commands().feedback(session, f);
            case Message.Cancel c -> reply(server.commands().cancelFromAgent(session, c));
            case Message.SensorSignal s -> server.sensor(session, s).ifPresent(this::reply);
            case Message.Query q -> reply(kb.query(q));
            case Message.Ask a -> reply(kb.ask(a));
            case Message.Assert a -> reply(kb.assertFrame(session, a));
            case Message.Destroy d -> kb.destroy(d).thenAccept(this::reply);
            case Message.Subscribe s -> reply(kb.subscribe(session, s));
            case Message.Unsubscribe u -> reply(kb.unsubscribe(session, u));
            case Message.Push p -> reply(kb.push(session, p));
            case Message.Pull p -> reply(kb.pull(p));
            case Message.Prove p -> kb.prove(p).thenAccept(this::reply);
            case Message.Why w -> kb.why(w).thenAccept(this::reply);
            case Message.WhyNot w -> kb.whyNot(w).thenAccept(this::reply);
            case Message.ErrorReply e -> LOG.info("Agent {} reports {}: {}", session, e.code(), e.message());
            case Message.AuthResult m -> serverOnly("auth_result");
            case Message.Ack m -> serverOnly("ack");
            case Message.Frames m -> serverOnly("frames");
            case Message.Answer m -> serverOnly("answer");
            case Message.Changed m -> serverOnly("changed");
            case Message.Proofs m -> serverOnly("proofs");
            case Message.Explained m -> serverOnly("explained");
            case Message.NotFired m -> serverOnly("not_fired");
        }
    }

    @Override public void userEventTriggered(ChannelHandlerContext ctx, Object event) throws Exception {
        if (event instanceof IdleStateEvent idle) {
            if (idle.state() == IdleState.READER_IDLE) {
                LOG.info("Closing {}: no message within the heartbeat timeout.", session);
                server.out().closeWith(session, ErrorReply.of(ErrorCode.HEARTBEAT_TIMEOUT,
                        "Nothing was heard from this connection within the heartbeat timeout."));
            }
            return;
        }
        super.userEventTriggered(ctx, event);
    }

    @Override public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        if (cause instanceof IOException) {
            LOG.debug("Connection {} failed: {}", session, cause.toString());
            ctx.close();
            return;
        }
        if (cause.getCause() instanceof javax.net.ssl.SSLException || cause instanceof javax.net.ssl.SSLException) {
            // No error message can be sent without a TLS session: just close.
            LOG.info("Closing {}: TLS failed: {}", session, cause.getCause() == null ? cause : cause.getCause());
            metrics.protocolErrors.incrementAndGet();
            ctx.close();
            return;
        }
        ErrorReply error = toError(cause);
        if (error.code() == ErrorCode.INTERNAL) {
            LOG.error("Internal error on connection {}.", session, cause);
        } else {
            LOG.info("Closing {}: {} ({})", session, error.message(), error.code());
        }
        refuse(error);
    }

    private static ErrorReply toError(Throwable cause) {
        if (cause instanceof DecoderException && cause.getCause() instanceof ProtocolException p) {
            return ErrorReply.of(p.code(), p.getMessage());
        }
        if (cause instanceof TooLongFrameException || cause instanceof CorruptedFrameException) {
            return ErrorReply.of(ErrorCode.FRAME_TOO_LARGE, tooLong(cause));
        }
        if (cause instanceof ProtocolException p) {
            return ErrorReply.of(p.code(), p.getMessage());
        }
        return ErrorReply.of(ErrorCode.INTERNAL, "The server failed on this connection: " + cause);
    }

    /**
     * The sentence for an oversize frame, with the payload's size and the limit as docs/protocol.md counts them;
     * Netty's own message counts the 4-byte length prefix in both ("exceeds 1048580: 2021257 - discarded").
     */
    private static String tooLong(Throwable cause) {
        Matcher m = cause.getMessage() == null ? null : NETTY_TOO_LONG.matcher(cause.getMessage());
        if (m != null && m.find()) {
            long limit = Long.parseLong(m.group(1)) - Framing.LENGTH_BYTES;
            long length = Long.parseLong(m.group(2)) - Framing.LENGTH_BYTES;
            return "A frame of " + length + " bytes is longer than this server accepts (" + limit + " bytes at most).";
        }
        return "The frame is longer than this server accepts: " + cause.getMessage();
    }

    private void serverOnly(String type) {
        refuse(ErrorReply.of(ErrorCode.BAD_MESSAGE, "'" + type + "' is sent by the server, never to it."));
    }

    private void reply(Message answer) {
        server.out().send(session, answer);
    }

    private void refuse(ErrorReply error) {
        metrics.protocolErrors.incrementAndGet();
        server.out().closeWith(session, error);
    }
}
