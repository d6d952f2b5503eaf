package org.kicnp.bench;

import java.time.Duration;
import org.HdrHistogram.Histogram;

/**
 * The open-loop result at one offered rate: latency percentiles in milliseconds (delivery time minus intended
 * send time), the rate actually delivered within the window, how many intended messages never arrived, and what the
 * window cost: the hub's and the client loops' CPU time per delivered message, and the share of the whole machine
 * (all cores, every process) that was busy, in % (the headroom the tail depends on), and the share the hypervisor
 * took (steal, in %: each steal stalls whatever ran on that core, and the tail follows it).
 */
record LatencyFigures(int offeredPerSecond, double p50Millis, double p99Millis, double p999Millis, double maxMillis,
                      double deliveredPerSecond, long lost, double hubCpuMicrosPerMsg, double clientCpuMicrosPerMsg,
                      double machineBusyPercent, double machineStealPercent) {

    static LatencyFigures of(int offered, Histogram micros, long expected, Duration window, long hubCpuNanos,
            long clientCpuNanos, double machineBusyPercent, double machineStealPercent) {
        long n = Math.max(1, micros.getTotalCount());
        return new LatencyFigures(offered, ms(micros.getValueAtPercentile(50)), ms(micros.getValueAtPercentile(99)),
                ms(micros.getValueAtPercentile(99.9)), ms(micros.getMaxValue()),
                micros.getTotalCount() * 1e9 / window.toNanos(), Math.max(0, expected - micros.getTotalCount()),
                hubCpuNanos / 1e3 / n, clientCpuNanos / 1e3 / n, machineBusyPercent, machineStealPercent);
    }

    private static double ms(long micros) {
        return micros / 1000.0;
    }
}
