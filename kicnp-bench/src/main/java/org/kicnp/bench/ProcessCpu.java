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
     * The machine's CPU time so far, all cores, in clock ticks: {busy, total}, from the first line of
     * {@code /proc/stat}. Busy is user, nice, system, irq, softirq and steal; the total adds idle and iowait (a thread
     * waiting in io_uring counts as iowait, so iowait is idle here). {0, 0} if it cannot be read.
     */
    static long[] machineTicks() {
        try {
            String stat;
            try (FileInputStream in = new FileInputStream("/proc/stat")) {
                stat = new String(in.readNBytes(256), StandardCharsets.US_ASCII);
            }
            String[] f = stat.substring(0, stat.indexOf('\n')).trim().split(" +");
            long idle = Long.parseLong(f[4]) + Long.parseLong(f[5]);
            long busy = 0;
            for (int i : new int[] {1, 2, 3, 6, 7, 8}) {
                busy += Long.parseLong(f[i]);
            }
            return new long[] {busy, busy + idle};
        } catch (IOException | RuntimeException e) {
            return new long[] {0, 0};
        }
    }

    /** The share of the machine's CPU time (all cores) that was busy between two {@link #machineTicks()}, in %. */
    static double busyPercent(long[] before, long[] after) {
        long total = after[1] - before[1];
        return total <= 0 ? 0 : 100.0 * (after[0] - before[0]) / total;
    }
}
