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
}
