package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class ProcessCpuTest {

    @Test
    void machineIdle_whileThisThreadSpins_showsTheMachineBusy() {
        long[] before = ProcessCpu.machineIdle();
        long end = System.nanoTime() + 500_000_000L;
        long x = 0;
        while (System.nanoTime() < end) {
            x += x * 31 + 7;
        }
        long[] after = ProcessCpu.machineIdle();

        assertThat(x).isNotZero();
        assertThat(after[2]).as("cores in /proc/stat").isEqualTo(before[2]).isPositive();
        assertThat(after[1] - before[1]).isGreaterThanOrEqualTo(500_000_000L);
        // one core of the machine's was kept busy all along: at least 1 / cores of it (less a tolerance)
        assertThat(ProcessCpu.busyPercent(before, after)).isGreaterThan(100.0 / after[2] * 0.8)
                .isLessThanOrEqualTo(100);
    }

    @Test
    void busyPercent_isOneLessTheIdleShareOfElapsedTimeTimesCores() {
        // 2 cores for 1 s = 200 ticks of capacity; 50 idle ticks -> 75 % busy
        assertThat(ProcessCpu.busyPercent(new long[] {1000, 0, 2}, new long[] {1050, 1_000_000_000L, 2}))
                .isCloseTo(75.0, org.assertj.core.data.Offset.offset(1e-9));
        assertThat(ProcessCpu.busyPercent(new long[] {1000, 0, 2}, new long[] {1200, 1_000_000_000L, 2})).isZero();
        assertThat(ProcessCpu.busyPercent(new long[] {0, 0, 0}, new long[] {0, 1_000_000_000L, 0})).isZero();
    }
}
