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
        if (!admit(to)) {
            return false;
        }
        to.enqueue(message);
        return true;
    }

    /**
     * Sends a whole frame as it is (a forwarded relay): the {@code length} bytes of {@code source} from {@code index},
     * which the caller keeps (its reference and indices are left as they were). On the receiver's own event loop the
     * bytes are copied at once ({@link Session#appendNow}); otherwise a retained slice of them is queued.
     */
    boolean forward(Session to, ByteBuf source, int index, int length) {
        if (!admit(to)) {
            return false;
        }
        if (!to.appendNow(source, index, length)) {
            to.enqueue(source.retainedSlice(index, length));
        }
        return true;
    }

    /**
     * Whether a message may be handed to the connection now (then it is counted as sent, and the caller hands it
     * over); when not, a message to a connection above its high mark is counted as shed, and the connection is
     * dropped after {@code maxShedBeforeDrop} in a row.
     */
    private boolean admit(Session to) {
        Channel ch = to.channel();
        if (!ch.isActive() || to.state() == Session.State.CLOSING) {
            return false;
        }
        if (ch.isWritable()) {
            if (to.shedInARow.get() != 0) {
                to.shedInARow.set(0);
            }
            metrics.sent.increment();
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
