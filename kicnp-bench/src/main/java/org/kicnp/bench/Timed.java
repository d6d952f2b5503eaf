package org.kicnp.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.OperatingSystemMXBean;
import java.util.function.Supplier;

/**
 * Times rounds of one operation by the wall clock, which is the figure reported, and also by the CPU time of the
 * whole process (all threads, garbage collection included): on a machine shared with other work the wall clock
 * grows while the CPU time stays close to what the operation costs.
 */
final class Timed {
    private final Samples wall = new Samples();
    private final Samples cpu = new Samples();

    /** Runs one round and records its wall-clock and CPU seconds. */
    <T> T time(Supplier<T> operation) {
        long cpuStart = processCpuNanos();
        long start = System.nanoTime();
        T result = operation.get();
        wall.add((System.nanoTime() - start) / 1e9);
        long cpuEnd = processCpuNanos();
        if (cpuStart >= 0 && cpuEnd >= 0) {
            cpu.add((cpuEnd - cpuStart) / 1e9);
        }
        return result;
    }

    Samples wall() {
        return wall;
    }

    /** CPU seconds per round; empty when the JVM cannot tell the process's CPU time. */
    Samples cpu() {
        return cpu;
    }

    private static long processCpuNanos() {
        OperatingSystemMXBean os = ManagementFactory.getOperatingSystemMXBean();
        return os instanceof com.sun.management.OperatingSystemMXBean sun ? sun.getProcessCpuTime() : -1;
    }
}
