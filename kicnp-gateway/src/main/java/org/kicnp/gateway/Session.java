package org.kicnp.gateway;

import static java.util.Objects.requireNonNull;

import io.netty.buffer.ByteBuf;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFutureListener;
import io.netty.util.internal.PlatformDependent;
import java.util.List;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.MessageCodec;

/**
 * One agent connection as the server agent sees it: who it is once authenticated, whether it registered, what it
 * subscribed to, and how many messages to it were shed in a row. State changes happen on the channel's event loop.
 *
 * <p>Outgoing messages wait in an outbox that the channel's event loop drains in one go, writing them all as one
 * buffer and flushing once: a burst of relays to one agent costs one wake-up, one buffer and one system call, not one
 * of each per message, whichever thread the messages come from. Messages queued on the channel's own loop while a
 * connection's reads are handled are drained when that read batch ends ({@link ReadBatch}); others by a task.
 */
final class Session {
    enum State { NEW, AUTHENTICATED, REGISTERED, CLOSING }

    /** The first size of a drain's buffer; it grows as needed. */
    private static final int BATCH_BYTES = 1024;

    private final Channel channel;
    private final MessageCodec codec;
    private final int maxFrameBytes;
    private volatile State state = State.NEW;
    private volatile String agent = "";
    private volatile AgentKind kind = AgentKind.SERVICE;
    private volatile List<String> capabilities = List.of();
    private final Set<String> subscriptions = ConcurrentHashMap.newKeySet();
    final AtomicInteger shedInARow = new AtomicInteger();
    /** Commands sent to this (robot) connection and not yet ended or failed. */
    final AtomicInteger commandsInFlight = new AtomicInteger();

    private final Queue<Object> outbox = PlatformDependent.newMpscQueue();
    private final AtomicBoolean drainScheduled = new AtomicBoolean();
    /** The drain as a task, made once rather than per message. */
    private final Runnable drainTask = this::drain;
    /** When the outbox was last written to the connection ({@link System#nanoTime}); read on the event loop. */
    private long lastWriteNanos = System.nanoTime();
    /**
     * Frames copied in on the channel's event loop while the outbox was empty ({@link #appendNow}), ahead of anything
     * queued after them: the next drain writes this buffer first and goes on filling it. Event loop only.
     */
    private ByteBuf pending;

    /** A last message, after which the connection closes. */
    private record Last(Message message) {
    }

    /** @param maxFrameBytes the longest answer sent as it is; a longer one is replaced by an error saying so */
    Session(Channel channel, MessageCodec codec, int maxFrameBytes) {
        this.channel = requireNonNull(channel, "channel");
        this.codec = requireNonNull(codec, "codec");
        this.maxFrameBytes = maxFrameBytes;
    }

    Channel channel() {
        return channel;
    }

    State state() {
        return state;
    }

    void authenticated(String name, AgentKind k) {
        this.agent = name;
        this.kind = k;
        this.state = State.AUTHENTICATED;
    }

    void registered(List<String> capabilityNames) {
        this.capabilities = List.copyOf(capabilityNames);
        this.state = State.REGISTERED;
    }

    /** Queues a message, or a whole frame to write as it is, for this connection; safe from any thread. */
    void enqueue(Object m) {
        outbox.offer(m);
        scheduleDrain();
    }

    /** Queues a last message, after which the connection closes; safe from any thread. */
    void enqueueLast(Message m) {
        outbox.offer(new Last(m));
        scheduleDrain();
    }

    /**
     * Copies a forwarded frame ({@code length} bytes of {@code source} from {@code index}, prefix included) straight
     * into the buffer the next drain writes, when called on this connection's event loop with nothing waiting in the
     * outbox; false, having done nothing, otherwise (the caller queues the frame). A relay between two connections of
     * one event loop then keeps no reference to the sender's read buffer and queues nothing: no slice, no queue node,
     * no garbage per relay. The order of messages is kept: the outbox is empty, so everything queued so far has been
     * written, and whatever is queued later is written after this buffer.
     */
    boolean appendNow(ByteBuf source, int index, int length) {
        if (!channel.eventLoop().inEventLoop() || !outbox.isEmpty()) {
            return false;
        }
        if (pending == null) {
            pending = channel.alloc().ioBuffer(Math.max(BATCH_BYTES, length));
        }
        pending.writeBytes(source, index, length);
        scheduleDrain();
        return true;
    }

    private void scheduleDrain() {
        if (drainScheduled.compareAndSet(false, true)) {
            io.netty.channel.EventLoop loop = channel.eventLoop();
            if (!(loop.inEventLoop() && ReadBatch.current().add(this, loop))) {
                loop.execute(drainTask);
            }
        }
    }

    /** Drains the outbox now, at the end of the read batch that wrote to it; on the channel's event loop only. */
    void drainNow() {
        drain();
    }

    /**
     * Writes everything queued, in order, as one buffer of frames (messages encoded, forwarded frames copied in),
     * then flushes once: one pipeline pass and one buffer per drain instead of one per message. Runs on the
     * channel's event loop.
     */
    private void drain() {
        drainScheduled.set(false); // before polling: a message queued from now on schedules another drain
        lastWriteNanos = System.nanoTime();
        ByteBuf batch = pending;
        pending = null;
        try {
            Object next;
            while ((next = outbox.poll()) != null) {
                if (next instanceof Last last) {
                    if (batch != null) {
                        channel.write(batch, channel.voidPromise());
                        batch = null;
                    }
                    channel.writeAndFlush(last.message()).addListener(ChannelFutureListener.CLOSE);
                } else {
                    if (batch == null) {
                        batch = channel.alloc().ioBuffer(BATCH_BYTES);
                    }
                    append(batch, next);
                }
            }
            if (batch != null) {
                channel.write(batch, channel.voidPromise());
                batch = null;
            }
        } finally {
            if (batch != null) {
                batch.release();
            }
            channel.flush();
        }
    }

    /** Appends one frame: a forwarded frame as it is (releasing it), or a message encoded. */
    private void append(ByteBuf batch, Object next) {
        if (next instanceof ByteBuf frame) {
            try {
                batch.writeBytes(frame, frame.readerIndex(), frame.readableBytes());
            } finally {
                frame.release();
            }
        } else {
            byte[] payload = MessageEncoder.payload(codec, (Message) next, maxFrameBytes);
            batch.writeInt(payload.length).writeBytes(payload);
        }
    }

    /** When messages were last written to this connection ({@link System#nanoTime}); on the event loop only. */
    long lastWriteNanos() {
        return lastWriteNanos;
    }

    void closing() {
        this.state = State.CLOSING;
    }

    /** The authenticated agent name; empty before authentication. */
    String agent() {
        return agent;
    }

    AgentKind kind() {
        return kind;
    }

    List<String> capabilities() {
        return capabilities;
    }

    Set<String> subscriptions() {
        return subscriptions;
    }

    @Override public String toString() {
        return agent.isEmpty() ? String.valueOf(channel.remoteAddress()) : "'" + agent + "'";
    }
}
