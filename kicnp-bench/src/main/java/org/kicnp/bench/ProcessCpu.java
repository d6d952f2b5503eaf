package org.kicnp.bench;

import java.io.FileInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;

/**
 * The CPU time of another process, from {@code /proc}: what the bench charges to a hub running on its own. Read with
 * a {@link FileInputStream} (its own native read), not {@code Files}: NIO's file reads share {@code sun.nio.ch.IOUtil}
 * with the clients' socket reads, and a file read there once the socket path is compiled fails the compiled code's
 * class check and deoptimises the clients' read path just before a measurement (seen in the deoptimisation log).
 */
final class ProcessCpu {
    private ProcessCpu() {
    }

    /** The process's CPU time so far (user and system), in nanoseconds; 0 if it cannot be read. */
    static long nanos(long pid) {
        try {
            String stat;
            try (FileInputStream in = new FileInputStream("/proc/" + pid + "/stat")) {
                stat = new String(in.readAllBytes(), StandardCharsets.US_ASCII);
            }
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            long ticks = Long.parseLong(f[11]) + Long.parseLong(f[12]); // utime, stime (fields 14 and 15)
            return ticks * 10_000_000L; // USER_HZ is 100 on Linux
        } catch (IOException | RuntimeException e) {
            return 0;
        }
    }

    /**
     * A reading of the machine's idle time, from {@code /proc/stat}: idle plus iowait clock ticks of all cores (a
     * thread waiting in io_uring counts as iowait, so iowait is idle here), when it was read, and how many cores there
     * are (0 if it could not be read). The busy fields there (user, system, ...) are not used: they are sampled by the
     * scheduler tick, which misses most of a load made of short bursts (the open loop's), while idle and iowait are
     * measured when the cores enter and leave idle (over one open-loop run here the sampled busy fields gave 20 %
     * where the two processes' threads alone had used 37 % of the machine). Also the steal ticks: time the
     * hypervisor ran something else while this machine's cores had work (a virtual machine's cores are not its own);
     * a steal of a few milliseconds on the hub's core stalls every relay in flight, as a collection does.
     */
    record MachineIdle(long idleTicks, long nanoTime, int cores, long stealTicks) {
        MachineIdle(long idleTicks, long nanoTime, int cores) {
            this(idleTicks, nanoTime, cores, 0);
        }

        static MachineIdle now() {
            long now = System.nanoTime();
            try {
                String stat;
                try (FileInputStream in = new FileInputStream("/proc/stat")) {
                    stat = new String(in.readAllBytes(), StandardCharsets.US_ASCII);
                }
                String[] f = stat.substring(0, stat.indexOf('\n')).trim().split(" +");
                int cores = (int) stat.lines().filter(l -> l.startsWith("cpu") && Character.isDigit(l.charAt(3)))
                        .count();
                long steal = f.length > 8 ? Long.parseLong(f[8]) : 0;
                return new MachineIdle(Long.parseLong(f[4]) + Long.parseLong(f[5]), now, cores, steal);
            } catch (IOException | RuntimeException e) {
                return new MachineIdle(0, now, 0);
            }
        }

        /**
         * The share of the machine's CPU time (all cores, every process) that was busy since {@code before}, in %:
         * 100 × (1 − idle time / (elapsed time × cores)); 0 when either reading failed.
         */
        double busyPercentSince(MachineIdle before) {
            return percentOfCapacity(before, capacity -> capacity - (idleTicks - before.idleTicks));
        }

        /**
         * The share of the machine's CPU time that the hypervisor took (steal) since {@code before}, in %:
         * 100 × steal time / (elapsed time × cores); 0 when either reading failed.
         */
        double stealPercentSince(MachineIdle before) {
            return percentOfCapacity(before, capacity -> stealTicks - before.stealTicks);
        }

        /**
         * 100 × {@code ticks} / the clock ticks of all cores since {@code before} (given that capacity), within
         * [0, 100]; 0 when either reading failed.
         */
        private double percentOfCapacity(MachineIdle before, java.util.function.DoubleUnaryOperator ticks) {
            double capacityTicks = (nanoTime - before.nanoTime) / 1e9 * 100 * cores; // USER_HZ is 100 on Linux
            if (capacityTicks <= 0 || before.cores == 0) {
                return 0;
            }
            return Math.max(0, Math.min(100, 100 * ticks.applyAsDouble(capacityTicks) / capacityTicks));
        }
    }
}
