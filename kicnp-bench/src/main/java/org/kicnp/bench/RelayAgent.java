package org.kicnp.bench;

import io.netty.buffer.ByteBuf;
import io.netty.channel.Channel;

/**
 * One benchmark agent's connection and counters, on either protocol. Owned by its event loop ({@link RelayLoop}):
 * every field is read and written there only, so none needs synchronisation. Agents come in pairs on the same
 * loop, each sending to the other, so a delivery can free its sender's window without crossing threads.
 */
final class RelayAgent {
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

    /** Encodes one relay message from this agent to its peer, stamped with a time in bench nanos. */
    interface Encoder {
        ByteBuf encode(RelayAgent from, long stampNanos);
    }

    RelayAgent(int index, String name, RelayLoop loop, Encoder encoder) {
        this.index = index;
        this.name = name;
        this.loop = loop;
        this.encoder = encoder;
    }

    /** Writes one message stamped {@code stampNanos} to the hub; flushed later, once per batch, by the loop. */
    void send(long stampNanos) {
        sequence++;
        channel.write(encoder.encode(this, stampNanos), channel.voidPromise());
        loop.sent++;
        if (!dirty) {
            dirty = true;
            loop.dirty.add(this);
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
