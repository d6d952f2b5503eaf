package org.kicnp.bench;

import io.netty.channel.EventLoop;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.HdrHistogram.Histogram;

/**
 * The benchmark state of one client event loop and the agents it owns. Everything here runs on that loop:
 * sending (closed-loop window refills, open-loop ticks), counting deliveries, recording latencies, and flushing
 * each written channel once per batch of reads rather than once per message.
 *
 * <p>Open loop: each agent has a constant-rate schedule of intended send times, released by a 1 ms tick
 * ({@link Ticker}); a
 * message carries its <em>intended</em> time, and its latency is the delivery time minus that time. A stall
 * anywhere (client, hub, kernel) delays the sends behind it too, and every one of them is charged the full
 * delay, so coordinated omission is not hidden.
 */
final class RelayLoop {
    /** Bench time: nanoseconds since this class was loaded (plus one second, so stamps are never negative). */
    private static final long ORIGIN = System.nanoTime() - TimeUnit.SECONDS.toNanos(1);
    static final long TICK_NANOS = TimeUnit.MILLISECONDS.toNanos(1);
    /** The largest latency the histograms track: one minute, in microseconds. */
    private static final long MAX_MICROS = TimeUnit.MINUTES.toMicros(1);

    enum Mode { IDLE, CLOSED, OPEN }

    final EventLoop executor;
    final List<RelayAgent> agents = new ArrayList<>();
    final List<RelayAgent> dirty = new ArrayList<>();
    Mode mode = Mode.IDLE;
    /** Set when the driver closes the connections, so closing is not reported as a failure. */
    volatile boolean closing;
    long sent;
    long delivered;
    /**
     * Open loop: the latencies of the messages intended before the measured window (index 0, the warm-up, thrown
     * away) and within it (index 1). Both phases record through the same code (see {@link #phaseOf}).
     */
    private final Histogram[] phases = {new Histogram(MAX_MICROS, 3), new Histogram(MAX_MICROS, 3)};
    /** Open loop: the latencies of the messages intended within the measured window. */
    final Histogram latencies = phases[1];
    /** Open loop: messages whose intended time is in [recordFrom, recordUntil) are measured. */
    long recordFrom;
    long recordUntil;
    /** Open loop: no message is intended at or after this time (the end of the measured window). */
    long sendUntil;
    /** Open loop: the messages scheduled before the measured window (index 0) and within it (index 1). */
    private final long[] scheduled = new long[2];
    long periodNanos;
    /** Open loop: the schedule's start and the agents in all loops (for each agent's phase). */
    private long start;
    private int total;
    /** The open loop's tick as a task, made once: {@link Ticker} hands it to this loop every millisecond. */
    final Runnable tickTask = this::tick;

    RelayLoop(EventLoop executor) {
        this.executor = executor;
    }

    static long now() {
        return System.nanoTime() - ORIGIN;
    }

    /** Called by a client handler when {@code to} receives a message its peer stamped {@code stampNanos}. */
    void delivered(RelayAgent to, long stampNanos) {
        delivered++;
        RelayAgent from = to.peer;
        switch (mode) {
            case CLOSED -> {
                from.inFlight--;
                refill(from);
            }
            case OPEN -> {
                long micros = (now() - stampNanos) / 1_000;
                phases[phaseOf(stampNanos)].recordValue(Math.min(MAX_MICROS, Math.max(0, micros)));
            }
            case IDLE -> from.inFlight = Math.max(0, from.inFlight - 1);
        }
    }

    /**
     * The phase of an open-loop message intended at {@code stampNanos}: 0 before the measured window, 1 within it
     * (nothing is intended after it, see {@link #sendUntil}). Computed without a branch on purpose: a branch that is
     * first taken when the window opens is one the JIT compiled as never taken, so taking it would send the compiled
     * client code back to the interpreter (a deoptimisation) just as the first measured messages are sent and
     * received, and charge them a stall of the harness's own making. With the phase as an index, the warm-up runs the
     * very code that measures.
     */
    private int phaseOf(long stampNanos) {
        return (int) ((recordFrom - 1 - stampNanos) >>> 63);
    }

    /** Open loop: the messages scheduled within the measured window so far. */
    long scheduledInWindow() {
        return scheduled[1];
    }

    /** Called by a client handler at the end of a batch of reads: one flush per written channel. */
    void readComplete() {
        flushDirty();
    }

    private void flushDirty() {
        for (int i = 0; i < dirty.size(); i++) {
            dirty.get(i).flush();
        }
        dirty.clear();
    }

    private void refill(RelayAgent a) {
        if (a.window > 0 && a.inFlight < a.window) {
            long stamp = now();
            while (a.inFlight < a.window) {
                a.send(stamp);
                a.inFlight++;
            }
        }
    }

    /** Starts the closed loop: every agent keeps {@code window} messages outstanding. */
    void startClosed(int window) {
        mode = Mode.CLOSED;
        for (RelayAgent a : agents) {
            a.window = window;
            refill(a);
        }
        flushDirty();
    }

    /** Stops the closed loop; outstanding messages still arrive and are counted. */
    void stopClosed() {
        for (RelayAgent a : agents) {
            a.window = 0;
        }
        mode = Mode.IDLE;
    }

    int inFlight() {
        int n = 0;
        for (RelayAgent a : agents) {
            n += a.inFlight;
        }
        return n;
    }

    /**
     * Starts the open loop at {@code perAgentRate} messages per second per agent from {@code start}; agent
     * {@code k}'s phase is spread over one period by its position among {@code total} agents.
     */
    void startOpen(long start, long period, int total, long recordFrom, long recordUntil) {
        this.mode = Mode.OPEN;
        this.start = start;
        this.total = total;
        this.periodNanos = period;
        this.recordFrom = recordFrom;
        this.recordUntil = recordUntil;
        this.sendUntil = recordUntil;
        for (RelayAgent a : agents) {
            a.scheduled = 0;
            a.nextIntended = intended(start, a, total);
        }
        phases[0].reset();
        phases[1].reset();
        scheduled[0] = 0;
        scheduled[1] = 0;
    }

    /** An agent's next intended time: its constant-rate schedule, rounded down to the 1 ms tick that sends it. */
    private long intended(long start, RelayAgent a, int total) {
        long exact = start + a.index * periodNanos / total + a.scheduled * periodNanos;
        return start + (exact - start) / TICK_NANOS * TICK_NANOS;
    }

    /**
     * Sends every message due by now. Run on this loop by {@link Ticker}, on the grid the intended times are rounded
     * to (start + k ms), so a message is sent at its intended time rather than up to a tick after it; whatever delays
     * a tick is still charged to its messages.
     */
    void tick() {
        if (mode != Mode.OPEN) {
            return;
        }
        long now = now();
        for (int i = 0; i < agents.size(); i++) {
            RelayAgent a = agents.get(i);
            while (a.nextIntended <= now && a.nextIntended < sendUntil) {
                a.send(a.nextIntended);
                scheduled[phaseOf(a.nextIntended)]++;
                a.scheduled++;
                a.nextIntended = intended(start, a, total);
            }
        }
        flushDirty();
    }

    /** Ends the open loop (sending has already stopped at {@code sendUntil}). */
    void stopOpen() {
        mode = Mode.IDLE;
    }
}
