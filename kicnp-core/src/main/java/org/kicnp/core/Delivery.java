package org.kicnp.core;

import java.util.ArrayDeque;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.ReentrantLock;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Hands a knowledge base's committed batches to its listeners, one batch at a time and in commit order, whichever
 * threads commit them: a batch is {@linkplain #queue readied} under the knowledge base's write lock, the order of
 * commits, and {@linkplain #deliver delivered} after that lock is released, so that listeners may read the knowledge
 * base and change it. A change a listener makes is delivered after the batch it is hearing, by the same loop.
 */
final class Delivery {
    /** Logged under the knowledge base's name, where its listeners' failures have always been reported. */
    private static final Logger LOG = LoggerFactory.getLogger(KnowledgeBase.class);

    private final List<KnowledgeListener> listeners = new CopyOnWriteArrayList<>();
    private final ConcurrentLinkedQueue<ChangeSet> undelivered = new ConcurrentLinkedQueue<>();
    private final ReentrantLock delivery = new ReentrantLock();
    /**
     * While a thread {@linkplain KnowledgeBase#hold holds} the knowledge base: the batches it has committed and not yet
     * delivered, in commit order, and whether it is delivering one now (a listener's change then waits its turn here).
     * Used by the holding thread only, under both locks.
     */
    private final ArrayDeque<ChangeSet> held = new ArrayDeque<>();
    private boolean deliveringHeld;

    void add(KnowledgeListener listener) {
        listeners.add(listener);
    }

    void remove(KnowledgeListener listener) {
        listeners.remove(listener);
    }

    /**
     * Readies a batch just committed for the listeners, under the write lock, so that batches reach them in commit
     * order. When this thread can take the delivery lock at once and no batch waits to be delivered, every batch
     * committed before this one has been delivered: it keeps the delivery lock and answers true, and the caller hands
     * the batch to the listeners itself once the write lock is released (the common case of one thread making changes,
     * without a trip through the queue). Otherwise the batch joins the queue and the answer is false. An empty batch
     * is not delivered.
     */
    boolean queue(ChangeSet cs) {
        if (cs.isEmpty()) {
            return false;
        }
        if (!delivery.isHeldByCurrentThread() && delivery.tryLock()) {
            if (undelivered.isEmpty()) {
                return true;
            }
            delivery.unlock();
        }
        undelivered.add(cs);
        return false;
    }

    /**
     * After the write lock is released: delivers {@code cs} first when {@link #queue} kept the delivery lock for it
     * ({@code first}), then every queued batch, in order. A change made by a listener is delivered by the outer loop.
     */
    void deliver(ChangeSet cs, boolean first) {
        if (first) {
            try {
                notifyListeners(cs);
                drainQueue();
            } finally {
                delivery.unlock();
            }
        } else if (!cs.isEmpty()) {
            deliver();
        }
    }

    /**
     * Starts a hold for this thread: takes the delivery lock (before the write lock, the order {@link #deliver} takes
     * them in when a listener commits), unless this thread is delivering a batch now. Then the answer is false and
     * there is no hold: its commits must wait for the batch being delivered to reach every listener.
     */
    boolean beginHold() {
        if (delivery.isHeldByCurrentThread()) {
            return false;
        }
        delivery.lock();
        return true;
    }

    /**
     * Once the hold has the write lock too: delivers what was queued before it, in order, before anything the holding
     * thread commits.
     */
    void heldFromNow() {
        ChangeSet cs;
        while ((cs = undelivered.poll()) != null) {
            held.add(cs);
        }
        deliverHeld();
    }

    /**
     * A batch the holding thread committed: delivered now, in this thread, unless this thread is delivering one
     * already (a listener's change), which then delivers it next.
     */
    void deliverHeld(ChangeSet cs) {
        if (!cs.isEmpty()) {
            held.add(cs);
            deliverHeld();
        }
    }

    private void deliverHeld() {
        if (deliveringHeld) {
            return;
        }
        deliveringHeld = true;
        try {
            ChangeSet cs;
            while ((cs = held.poll()) != null) {
                notifyListeners(cs);
            }
        } finally {
            deliveringHeld = false;
        }
    }

    /** Whether the holding thread is delivering a batch now (it is in a listener). */
    boolean deliveringHeld() {
        return deliveringHeld;
    }

    /** Ends a hold once the write lock is released: every batch it committed has been delivered. */
    void endHold() {
        delivery.unlock();
    }

    /** Delivers the queued batches in order; a change made by a listener is delivered by the outer loop. */
    private void deliver() {
        if (delivery.isHeldByCurrentThread()) {
            return;
        }
        delivery.lock();
        try {
            drainQueue();
        } finally {
            delivery.unlock();
        }
    }

    private void drainQueue() {
        ChangeSet cs;
        while ((cs = undelivered.poll()) != null) {
            notifyListeners(cs);
        }
    }

    private void notifyListeners(ChangeSet cs) {
        for (KnowledgeListener l : listeners) {
            try {
                l.changed(cs);
            } catch (RuntimeException e) {
                LOG.error("Knowledge listener {} failed on version {}", l, cs.version(), e);
            }
        }
    }
}
