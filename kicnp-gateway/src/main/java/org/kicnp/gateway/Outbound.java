package org.kicnp.gateway;

import io.netty.buffer.ByteBuf;
import io.netty.channel.Channel;
import java.util.concurrent.TimeUnit;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.ErrorReply;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Sends to agents without ever queueing without bound. A connection above its write-buffer high mark (it is not
 * reading) gets nothing more: messages are shed and counted, and after {@code maxShedBeforeDrop} in a row the
 * connection is told {@code overloaded} and closed. Safe from any thread. Messages go through the session's outbox,
 * written and flushed once per batch on the connection's event loop (see {@link Session}).
 */
final class Outbound {
    private static final Logger LOG = LoggerFactory.getLogger(Outbound.class);

    private final GatewayMetrics metrics;
    private final int maxShedBeforeDrop;

    Outbound(GatewayMetrics metrics, int maxShedBeforeDrop) {
        this.metrics = metrics;
        this.maxShedBeforeDrop = maxShedBeforeDrop;
    }

    /** Sends a message; says whether it was handed to the connection (false: closed or shed). */
    boolean send(Session to, Message message) {
        return admit(to, message);
    }

    /**
     * Sends a whole frame as it is (a forwarded relay), taking over the caller's reference to it: the frame is
     * released here when it is not handed to the connection. The frame's indices are never moved, so one buffer
     * may go to several connections, each with its own reference.
     */
    boolean sendFrame(Session to, ByteBuf frame) {
        boolean sent = false;
        try {
            sent = admit(to, frame);
            return sent;
        } finally {
            if (!sent) {
                frame.release();
            }
        }
    }

    private boolean admit(Session to, Object message) {
        Channel ch = to.channel();
        if (!ch.isActive() || to.state() == Session.State.CLOSING) {
            return false;
        }
        if (ch.isWritable()) {
            if (to.shedInARow.get() != 0) {
                to.shedInARow.set(0);
            }
            metrics.sent.increment();
            to.enqueue(message);
            return true;
        }
        metrics.shed.incrementAndGet();
        if (to.shedInARow.incrementAndGet() == maxShedBeforeDrop) {
            metrics.slowConsumersDropped.incrementAndGet();
            LOG.warn("Dropping {}: {} messages in a row were shed because it does not read.", to, maxShedBeforeDrop);
            closeWith(to, ErrorReply.of(ErrorCode.OVERLOADED, "The server dropped this connection: "
                    + maxShedBeforeDrop + " messages in a row could not be sent because it does not read."));
        }
        return false;
    }

    /** Sends a last error and closes the connection once it is written (or at once, if it cannot be). */
    void closeWith(Session to, ErrorReply error) {
        to.closing();
        Channel ch = to.channel();
        if (!ch.isActive()) {
            return;
        }
        if (!ch.isWritable()) {
            ch.close(); // it does not read: the error would only wait behind what is queued
            return;
        }
        metrics.sent.increment();
        to.enqueueLast(error); // behind what is already queued, so the order of messages is kept
        ch.eventLoop().schedule(() -> ch.close(), 2, TimeUnit.SECONDS); // in case the peer never reads it
    }
}
