package org.kicnp.bench;

import io.netty.buffer.ByteBuf;
import io.netty.channel.Channel;

/**
 * One benchmark agent's connection and counters, on either protocol. Owned by its event loop ({@link RelayLoop}):
 * every field is read and written there only, so none needs synchronisation. Agents come in pairs on the same
 * loop, each sending to the other, so a delivery can free its sender's window without crossing threads.
 */
final class RelayAgent {
    private static final int BATCH_BYTES = 2048;

    final int index;
    final String name;
    final RelayLoop loop;
    final Encoder encoder;
    RelayAgent peer;
    Channel channel;

    /** Messages sent by this agent and not yet delivered to its peer (closed loop). */
    int inFlight;
    /** The closed-loop window; 0 stops the closed loop. */
    int window;
    /** The intended send time of this agent's next open-loop message, in bench nanos. */
    long nextIntended;
    /** How many open-loop messages this agent has been scheduled (its schedule position). */
    long scheduled;
    long sequence;
    boolean dirty;
    /** The messages written since the last flush, back to back in one buffer; null when there are none. */
    private ByteBuf pending;

    /** Appends one relay message from this agent to its peer, stamped with a time in bench nanos, to {@code out}. */
    interface Encoder {
        void encode(RelayAgent from, long stampNanos, ByteBuf out);
    }

    RelayAgent(int index, String name, RelayLoop loop, Encoder encoder) {
        this.index = index;
        this.name = name;
        this.loop = loop;
        this.encoder = encoder;
    }

    /**
     * Sends one message stamped {@code stampNanos} to the hub: appended to this agent's batch, which the loop writes
     * and flushes once per batch of reads or ticks ({@link #flush}). Each message is still its own frame (or MQTT
     * packet) on the wire; only the buffer and the system call are shared, as any batching client does.
     */
    void send(long stampNanos) {
        sequence++;
        if (pending == null) {
            pending = channel.alloc().ioBuffer(BATCH_BYTES);
        }
        encoder.encode(this, stampNanos, pending);
        loop.sent++;
        if (!dirty) {
            dirty = true;
            loop.dirty.add(this);
        }
    }

    /** Writes the batch and flushes the connection. */
    void flush() {
        dirty = false;
        if (pending != null) {
            channel.write(pending, channel.voidPromise());
            pending = null;
        }
        channel.flush();
    }

    /** Drops an unsent batch (the driver is closing). */
    void discard() {
        if (pending != null) {
            pending.release();
            pending = null;
        }
    }

    /** A bench agent's name: fixed width, so every message has the same size. */
    static String nameOf(int index) {
        return String.format(java.util.Locale.ROOT, "a%05d", index);
    }

    @Override public String toString() {
        return "'" + name + "'";
    }
}
