package org.kicnp.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;

/**
 * What one engine did in one timed run: how many rules fired, the wall-clock time to quiescence and the CPU time of
 * the thread that ran it (both engines run on the calling thread; CPU time shrugs off other processes on a busy
 * machine, wall time is what a user waits).
 */
record EngineResult(long firings, long nanos, long cpuNanos) {
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    double seconds() {
        return nanos / 1e9;
    }

    double cpuSeconds() {
        return cpuNanos / 1e9;
    }

    /** The current thread's CPU time in nanoseconds, or 0 where the JVM cannot tell. */
    static long threadCpuNanos() {
        return THREADS.isCurrentThreadCpuTimeSupported() ? THREADS.getCurrentThreadCpuTime() : 0;
    }
}
