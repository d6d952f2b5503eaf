package org.kicnp.editor;

import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * Passes on at most one snapshot per {@link #PERIOD_MS} milliseconds, always the newest: a simulator streaming at
 * 60 Hz must not flood the pages. A snapshot arriving within the period waits for its end and replaces any older
 * one still waiting; so the last snapshot of a burst is always delivered.
 */
final class WorldThrottle implements Consumer<WorldSnapshot>, AutoCloseable {
    static final long PERIOD_MS = 100;

    private final Consumer<WorldSnapshot> out;
    private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "kicnp-editor-world");
        t.setDaemon(true);
        return t;
    });
    private WorldSnapshot pending;
    private boolean scheduled;
    private long lastSentNanos = System.nanoTime() - TimeUnit.MILLISECONDS.toNanos(PERIOD_MS);

    WorldThrottle(Consumer<WorldSnapshot> out) {
        this.out = out;
    }

    @Override public void accept(WorldSnapshot snapshot) {
        synchronized (this) {
            pending = snapshot;
            if (scheduled || timer.isShutdown()) {
                return;
            }
            scheduled = true;
            long due = lastSentNanos + TimeUnit.MILLISECONDS.toNanos(PERIOD_MS) - System.nanoTime();
            timer.schedule(this::flush, Math.max(0, due), TimeUnit.NANOSECONDS);
        }
    }

    private void flush() {
        WorldSnapshot next;
        synchronized (this) {
            next = pending;
            pending = null;
            scheduled = false;
            lastSentNanos = System.nanoTime();
        }
        if (next != null) {
            out.accept(next);
        }
    }

    @Override public void close() {
        timer.shutdownNow();
    }
}
