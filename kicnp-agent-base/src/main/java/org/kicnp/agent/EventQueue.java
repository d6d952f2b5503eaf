package org.kicnp.agent;

import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * An agent's event thread and its bounded queue: relays, change notifications and life-cycle callbacks run on one
 * virtual thread, in the order they came. Adding never blocks, so the connection's reader goes on reading answers,
 * commands and heartbeats behind a burst that the agent's handlers cannot keep up with; were it to wait for room, a
 * request made from a handler would wait for an answer that nobody reads. When {@value #CAPACITY} events wait, the
 * oldest relay or change is dropped to make room — the newest say most about the present — and counted
 * ({@link #dropped()}); a warning is logged at the first drop and at every 1,000th. Life-cycle callbacks are dropped
 * only when nothing else waits, which a few callbacks per connection never fill.
 */
final class EventQueue implements AutoCloseable {
    /** How many events may wait for the event thread. */
    static final int CAPACITY = 10_000;
    private static final Logger LOG = LoggerFactory.getLogger(EventQueue.class);

    /** A relay or a change notification: what is dropped first when the queue is full. */
    private record Delivery(Runnable handler) implements Runnable {
        @Override public void run() {
            handler.run();
        }
    }

    private final String agent;
    private final AtomicLong dropped = new AtomicLong();
    private final ThreadPoolExecutor thread;

    EventQueue(String agent) {
        this.agent = agent;
        this.thread = new ThreadPoolExecutor(1, 1, 0, TimeUnit.MILLISECONDS, new ArrayBlockingQueue<>(CAPACITY),
                Thread.ofVirtual().name("agent-events").factory(), (task, pool) -> overflow(task, pool));
    }

    /** Queues a relay or change notification for its handler. */
    void deliver(Runnable handler) {
        thread.execute(new Delivery(handler));
    }

    /** Queues a life-cycle callback ({@code onConnected}, …), behind what waits already. */
    void callback(Runnable callback) {
        thread.execute(callback);
    }

    /** How many events were dropped because {@value #CAPACITY} were waiting. */
    long dropped() {
        return dropped.get();
    }

    /**
     * Makes room for a new event by dropping the oldest relay or change (or, when none waits, the new event), and
     * counts what it dropped. The event thread takes events meanwhile: an event it took was delivered, not dropped, so
     * only one this method took out of the queue itself is counted, and when the thread made room the new event goes
     * in without dropping anything.
     */
    private void overflow(Runnable task, ThreadPoolExecutor pool) {
        if (pool.isShutdown()) {
            return;
        }
        BlockingQueue<Runnable> queue = pool.getQueue();
        if (removeOldestDelivery(queue)) {
            countDrop();
            pool.execute(task);
        } else if (queue.remainingCapacity() > 0) {
            pool.execute(task);
        } else {
            countDrop(); // only life-cycle callbacks wait: the new event goes
        }
    }

    private void countDrop() {
        long n = dropped.incrementAndGet();
        if (n == 1 || n % 1000 == 0) {
            LOG.warn("Agent '{}' dropped its oldest waiting relay or change: {} events were waiting for onRelay and "
                    + "onChanged, which do not keep up ({} dropped so far).", agent, CAPACITY, n);
        }
    }

    /** Takes the oldest relay or change out of the queue; false when none was left to take (the thread took it). */
    private static boolean removeOldestDelivery(BlockingQueue<Runnable> queue) {
        for (Runnable r : queue) {
            if (r instanceof Delivery && queue.remove(r)) {
                return true; // removed by this call: the event thread did not take it first
            }
        }
        return false;
    }

    /** Stops the event thread; what still waits is not run. */
    @Override public void close() {
        thread.shutdownNow();
    }
}
