package org.kicnp.script;

import java.time.Duration;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

import org.graalvm.polyglot.Context;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Enforces the wall-clock limit. A run registers a {@link Guard} with its deadline; one shared daemon thread
 * looks at the registered guards every tick and cancels (closes) the context of a run past its deadline. The
 * close runs on a separate thread so one slow cancellation cannot delay the others. Registering costs a set
 * insertion, far less than arming a timer per run, which matters for runs of a few microseconds.
 */
final class Watchdog implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(Watchdog.class);

    private final Set<Guard> active = ConcurrentHashMap.newKeySet();
    private final long tickNanos;
    private final Thread ticker;
    private final ExecutorService closers;
    private volatile boolean closed;

    /** A watchdog whose deadlines are checked every {@code tick}. */
    Watchdog(Duration tick) {
        this.tickNanos = tick.toNanos();
        this.closers = Executors.newCachedThreadPool(runnable -> daemon(runnable, "kicnp-script-stopper"));
        this.ticker = daemon(this::loop, "kicnp-script-watchdog");
        ticker.start();
    }

    /** The tick for a time limit: a tenth of it, between 1 ms and 50 ms. */
    static Duration tickFor(Duration limit) {
        long millis = Math.clamp(limit.toMillis() / 10, 1, 50);
        return Duration.ofMillis(millis);
    }

    /** Starts watching one run of {@code context}; the caller must {@link Guard#finish()} it. */
    Guard watch(Context context, Duration limit) {
        Guard guard = new Guard(context, System.nanoTime() + limit.toNanos());
        active.add(guard);
        return guard;
    }

    @Override public void close() {
        closed = true;
        LockSupport.unpark(ticker);
        closers.shutdown();
    }

    private void loop() {
        while (!closed) {
            LockSupport.parkNanos(tickNanos);
            long now = System.nanoTime();
            for (Guard guard : active) {
                if (now - guard.deadline >= 0) {
                    guard.fire();
                }
            }
        }
    }

    private static Thread daemon(Runnable runnable, String name) {
        Thread thread = new Thread(runnable, name);
        thread.setDaemon(true);
        return thread;
    }

    /** The watch over one run. Exactly one of {@link #finish()} (the run) and the watchdog wins. */
    final class Guard {
        private static final int RUNNING = 0;
        private static final int FINISHED = 1;
        private static final int STOPPED = 2;

        private final Context context;
        private final long deadline;
        private final AtomicInteger state = new AtomicInteger(RUNNING);

        private Guard(Context context, long deadline) {
            this.context = context;
            this.deadline = deadline;
        }

        private void fire() {
            if (state.compareAndSet(RUNNING, STOPPED)) {
                active.remove(this);
                closers.execute(() -> {
                    try {
                        context.close(true);
                    } catch (RuntimeException e) {
                        LOG.debug("Cancelling an overrunning script context failed.", e);
                    }
                });
            }
        }

        /**
         * Ends the watch. Returns {@code true} if the run finished in time, {@code false} if the watchdog already
         * stopped it (the context is then closed or being closed and must be discarded). Idempotent.
         */
        boolean finish() {
            if (state.compareAndSet(RUNNING, FINISHED)) {
                active.remove(this);
            }
            return state.get() == FINISHED;
        }
    }
}
