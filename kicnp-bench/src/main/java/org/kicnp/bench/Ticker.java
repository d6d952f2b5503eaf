package org.kicnp.bench;

import java.util.concurrent.locks.LockSupport;

/**
 * The open loop's clock: one thread that wakes on the 1 ms grid of intended send times and hands each client loop
 * its tick ({@link RelayLoop#tick}, through {@link RelayDriver}). Not a scheduled task on each event loop: Netty's NIO loop waits for its next
 * scheduled task in {@code Selector.select(timeoutMillis)}, rounded to whole milliseconds, so its ticks fired up to
 * half a millisecond after their grid time (every message in them charged that), and for the last half millisecond
 * before each deadline it polls {@code selectNow()} in a loop, burning CPU the hub needed on a shared machine. This
 * thread sleeps with {@link LockSupport#parkNanos} (sub-millisecond timers) instead. A tick that comes late still sends
 * everything due by then, and each message is still charged from its intended time: nothing is hidden.
 */
final class Ticker {
    private final Thread thread;
    private volatile boolean stopped;

    private Ticker(Runnable onTick, long start, long until) {
        thread = Thread.ofPlatform().name("relay-ticker").daemon().unstarted(() -> run(onTick, start, until));
    }

    /**
     * Starts ticking at bench time {@code start} and on every millisecond of its grid after, up to and including
     * {@code until}.
     *
     * @param onTick run on the ticker's thread at each tick: it hands the loops their ticks, and must be quick
     */
    static Ticker start(Runnable onTick, long start, long until) {
        Ticker t = new Ticker(onTick, start, until);
        t.thread.start();
        return t;
    }

    private void run(Runnable onTick, long start, long until) {
        long next = start;
        while (!stopped) {
            long wait = next - RelayLoop.now();
            if (wait > 0) {
                LockSupport.parkNanos(wait);
                continue; // woken early (or spuriously): wait again for the grid time
            }
            onTick.run();
            if (next >= until) {
                return;
            }
            // The next grid time after now: a late wake-up ticks once for everything due, then keeps to the grid.
            long now = RelayLoop.now();
            next += Math.max(1, (now - next) / RelayLoop.TICK_NANOS + 1) * RelayLoop.TICK_NANOS;
        }
    }

    /** Waits until the last tick (at {@code until}) has been handed to the loops. */
    void awaitEnd() throws InterruptedException {
        thread.join();
    }

    /** Stops ticking (if it has not ended) and waits for the thread to end. */
    void stop() throws InterruptedException {
        stopped = true;
        LockSupport.unpark(thread);
        thread.join();
    }
}
