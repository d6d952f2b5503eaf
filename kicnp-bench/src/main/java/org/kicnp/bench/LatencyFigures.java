package org.kicnp.bench;

import java.time.Duration;
import org.HdrHistogram.Histogram;

/**
 * The open-loop result at one offered rate: latency percentiles in milliseconds (delivery time minus intended
 * send time), the rate actually delivered within the window, and how many intended messages never arrived.
 */
record LatencyFigures(int offeredPerSecond, double p50Millis, double p99Millis, double p999Millis, double maxMillis,
                      double deliveredPerSecond, long lost) {

    static LatencyFigures of(int offered, Histogram micros, long expected, Duration window) {
        return new LatencyFigures(offered, ms(micros.getValueAtPercentile(50)), ms(micros.getValueAtPercentile(99)),
                ms(micros.getValueAtPercentile(99.9)), ms(micros.getMaxValue()),
                micros.getTotalCount() * 1e9 / window.toNanos(), Math.max(0, expected - micros.getTotalCount()));
    }

    private static double ms(long micros) {
        return micros / 1000.0;
    }
}
