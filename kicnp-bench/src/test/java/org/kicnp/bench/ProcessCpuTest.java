package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class ProcessCpuTest {

    @Test
    void machineTicks_countBusyWithinTheTotal_andGrowWhileThisThreadSpins() {
        long[] before = ProcessCpu.machineTicks();
        long end = System.nanoTime() + 300_000_000L;
        long x = 0;
        while (System.nanoTime() < end) {
            x += x * 31 + 7;
        }
        long[] after = ProcessCpu.machineTicks();

        assertThat(x).isNotZero();
        assertThat(before[0]).isPositive().isLessThanOrEqualTo(before[1]);
        assertThat(after[0] - before[0]).as("busy ticks over 300 ms of spinning").isPositive();
        assertThat(after[1] - before[1]).isGreaterThanOrEqualTo(after[0] - before[0]);
        assertThat(ProcessCpu.busyPercent(before, after)).isPositive().isLessThanOrEqualTo(100);
    }

    @Test
    void busyPercent_isTheBusyShareOfTheTicksBetweenTwoReadings() {
        assertThat(ProcessCpu.busyPercent(new long[] {100, 1000}, new long[] {175, 1100})).isEqualTo(75.0);
        assertThat(ProcessCpu.busyPercent(new long[] {100, 1000}, new long[] {100, 1000})).isZero();
    }
}
