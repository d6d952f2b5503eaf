package org.kicnp.gateway;

import io.netty.channel.EventLoop;
import io.netty.util.concurrent.FastThreadLocal;
import java.util.ArrayList;
import java.util.List;

/**
 * The sessions written to while one connection's batch of reads is handled, on that connection's event loop: they
 * are drained when the batch ends ({@code channelReadComplete}), so a relay read from one connection is written to
 * its receiver at once, rather than after the event loop has read every other ready connection too.
 *
 * <p>Why: an event loop reads all its ready connections first and runs its tasks after. With a drain task per
 * receiver, a relay waited for the whole round of reads; with 1,000 agents each sending now and then, a round holds
 * hundreds of connections, and a short stall (a collection, a thread preempted for a core) grew into rounds of
 * several milliseconds that every relay in them waited out. Drained at the end of its own read batch, a relay waits
 * only for the messages read with it, and what one batch sends to one receiver is still one write and one flush.
 *
 * <p>One instance per event-loop thread, used only there. Messages queued from other threads, or on the loop outside
 * a read batch (heartbeats, knowledge-base notifications), still schedule a drain task on the receiver's loop.
 */
final class ReadBatch {
    private static final FastThreadLocal<ReadBatch> CURRENT = new FastThreadLocal<>() {
        @Override protected ReadBatch initialValue() {
            return new ReadBatch();
        }
    };

    private final List<Session> pending = new ArrayList<>();
    private boolean open;
    private boolean safetyNetScheduled;

    private ReadBatch() {
    }

    /** This thread's batch; call on an event loop only. */
    static ReadBatch current() {
        return CURRENT.get();
    }

    /** Marks the start of a batch of reads (idempotent within one batch). */
    void open() {
        open = true;
    }

    /**
     * Takes a session to drain at the end of the batch; false when no batch is open on this thread, so the caller
     * schedules a drain task instead.
     */
    boolean add(Session s, EventLoop loop) {
        if (!open) {
            return false;
        }
        if (!safetyNetScheduled) {
            // Should a batch's end never be signalled, its sessions are still drained when the loop next runs its
            // tasks, as they were before batches existed. One task per round of reads, not one per batch.
            safetyNetScheduled = true;
            loop.execute(closeIfOpen);
        }
        pending.add(s);
        return true;
    }

    private final Runnable closeIfOpen = () -> {
        safetyNetScheduled = false;
        if (open) {
            close();
        }
    };

    /** Ends the batch: drains every session written to during it, in the order they were first written to. */
    void close() {
        open = false;
        // Indexed: a drain never adds to this list (the batch is closed), but stay safe if one did.
        for (int i = 0; i < pending.size(); i++) {
            pending.get(i).drainNow();
        }
        pending.clear();
    }
}
