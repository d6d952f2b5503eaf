package org.kicnp.core;

import java.util.concurrent.locks.ReentrantReadWriteLock;
import java.util.function.Supplier;

/**
 * Who may read and change a {@link KnowledgeBase} when, and how its committed batches reach the listeners: reads share
 * a lock, a commit takes it exclusively and {@linkplain Delivery readies} its batch there, in commit order, for the
 * listeners to hear once the lock is released; a thread's {@linkplain KnowledgeBase#hold hold} keeps both for a burst
 * of changes that then take neither. Kept apart from the knowledge base, which decides what a change does to the
 * frames, so that one class decides the concurrency.
 */
final class Access {
    private static final KnowledgeBase.Hold NO_HOLD = () -> { };

    private final ReentrantReadWriteLock lock = new ReentrantReadWriteLock();
    private final Delivery delivery = new Delivery();
    /**
     * The thread that holds the knowledge base ({@link #hold}), or null. Written by that thread only, under the write
     * lock; another thread may read a stale value, never its own thread.
     */
    private Thread holder;
    /** The hold was closed while its thread was in a listener: it ends once that delivery is over. */
    private boolean holdEnding;

    void addListener(KnowledgeListener listener) {
        delivery.add(listener);
    }

    void removeListener(KnowledgeListener listener) {
        delivery.remove(listener);
    }

    /** Runs {@code body} under the read lock (with none to take in this thread's hold). */
    <T> T read(Supplier<T> body) {
        if (holding()) {
            return body.get();
        }
        lock.readLock().lock();
        try {
            return body.get();
        } finally {
            lock.readLock().unlock();
        }
    }

    /** Runs {@code body}, which changes no frame, under the write lock. */
    void write(Runnable body) {
        lock.writeLock().lock();
        try {
            body.run();
        } finally {
            lock.writeLock().unlock();
        }
    }

    /**
     * Commits under the write lock and {@linkplain Delivery#queue readies} the change set there, in commit order; then,
     * with the lock released, hands it to the listeners. In a hold of this thread's, commits and delivers with no lock
     * to take.
     */
    ChangeSet applied(Supplier<ChangeSet> commit) {
        if (holding()) {
            return committedInHold(commit.get());
        }
        ChangeSet committed;
        boolean first;
        lock.writeLock().lock();
        try {
            committed = commit.get();
            first = delivery.queue(committed);
        } finally {
            lock.writeLock().unlock();
        }
        delivery.deliver(committed, first);
        return committed;
    }

    /** Whether this thread holds the knowledge base: it may then commit and read with no lock to take. */
    boolean holding() {
        return holder == Thread.currentThread();
    }

    /**
     * Delivers a change set this thread committed in its {@link #holding hold} and returns it: the part of
     * {@link #applied} after the commit, for a caller that commits without handing it a {@code Supplier} (the one
     * object a firing's commit would make for nothing but the hand-over).
     */
    ChangeSet committedInHold(ChangeSet committed) {
        delivery.deliverHeld(committed);
        endHoldIfAsked();
        return committed;
    }

    /** {@link KnowledgeBase#hold()}. */
    KnowledgeBase.Hold hold() {
        Thread me = Thread.currentThread();
        if (holder == me || !delivery.beginHold()) {
            return NO_HOLD;
        }
        lock.writeLock().lock();
        holder = me;
        try {
            delivery.heldFromNow(); // what other threads committed before the hold reaches the listeners first
        } catch (Throwable t) {
            endHold();
            throw t;
        }
        return new KnowledgeBase.Hold() {
            private boolean closed;

            @Override public void close() {
                if (closed || holder != Thread.currentThread()) {
                    return;
                }
                closed = true;
                if (delivery.deliveringHeld()) {
                    holdEnding = true;
                } else {
                    endHold();
                }
            }
        };
    }

    private void endHoldIfAsked() {
        if (holdEnding && !delivery.deliveringHeld()) {
            endHold();
        }
    }

    private void endHold() {
        holdEnding = false;
        holder = null;
        lock.writeLock().unlock();
        delivery.endHold();
    }
}
