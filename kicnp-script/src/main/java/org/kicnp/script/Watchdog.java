package org.kicnp.script;

import java.time.Duration;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.graalvm.polyglot.Context;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Enforces the wall-clock limit: one shared scheduler thread arms a timer per run and, when a run overruns,
 * cancels its context by closing it. The close itself runs on a separate thread so one slow cancellation
 * cannot delay the timers of other runs.
 */
final class Watchdog implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(Watchdog.class);

    private final ScheduledThreadPoolExecutor timers;
    private final ExecutorService closers;

    Watchdog() {
        timers = new ScheduledThreadPoolExecutor(1, daemon("kicnp-script-watchdog"));
        timers.setRemoveOnCancelPolicy(true);
        closers = Executors.newCachedThreadPool(daemon("kicnp-script-stopper"));
    }

    /** Arms the timer for one run of {@code context}; the caller must {@link Guard#finish()} it. */
    Guard watch(Context context, Duration limit) {
        Guard guard = new Guard(context);
        guard.timer = timers.schedule(guard::fire, limit.toNanos(), TimeUnit.NANOSECONDS);
        return guard;
    }

    @Override public void close() {
        timers.shutdownNow();
        closers.shutdown();
    }

    private static java.util.concurrent.ThreadFactory daemon(String name) {
        return runnable -> {
            Thread thread = new Thread(runnable, name);
            thread.setDaemon(true);
            return thread;
        };
    }

    /** The timer of one run. Exactly one of {@link #finish()} (the run) and the timer wins. */
    final class Guard {
        private static final int RUNNING = 0;
        private static final int FINISHED = 1;
        private static final int STOPPED = 2;

        private final Context context;
        private final AtomicInteger state = new AtomicInteger(RUNNING);
        private volatile ScheduledFuture<?> timer;

        private Guard(Context context) {
            this.context = context;
        }

        private void fire() {
            if (state.compareAndSet(RUNNING, STOPPED)) {
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
         * Ends the watch. Returns {@code true} if the run finished in time, {@code false} if the timer already
         * stopped it (the context is then closed or being closed and must be discarded). Idempotent.
         */
        boolean finish() {
            state.compareAndSet(RUNNING, FINISHED);
            ScheduledFuture<?> t = timer;
            if (t != null) {
                t.cancel(false);
            }
            return state.get() == FINISHED;
        }
    }
}
