package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import org.junit.jupiter.api.Test;

class ProcessCpuTest {

    @Test
    void machineIdle_whileThisThreadSpins_showsTheMachineBusy() {
        ProcessCpu.MachineIdle before = ProcessCpu.MachineIdle.now();
        long end = System.nanoTime() + 500_000_000L;
        long x = 0;
        while (System.nanoTime() < end) {
            x += x * 31 + 7;
        }
        ProcessCpu.MachineIdle after = ProcessCpu.MachineIdle.now();

        assertThat(x).isNotZero();
        assertThat(after.cores()).as("cores in /proc/stat").isEqualTo(before.cores()).isPositive();
        assertThat(after.nanoTime() - before.nanoTime()).isGreaterThanOrEqualTo(500_000_000L);
        // one of the machine's cores was kept busy all along: at least 1 / cores of it (less a tolerance)
        assertThat(after.busyPercentSince(before)).isGreaterThan(100.0 / after.cores() * 0.8).isLessThanOrEqualTo(100);
    }

    @Test
    void busyPercentSince_isOneLessTheIdleShareOfElapsedTimeTimesCores() {
        ProcessCpu.MachineIdle start = new ProcessCpu.MachineIdle(1000, 0, 2);
        // 2 cores for 1 s = 200 ticks of capacity; 50 idle ticks -> 75 % busy
        assertThat(new ProcessCpu.MachineIdle(1050, 1_000_000_000L, 2).busyPercentSince(start))
                .isCloseTo(75.0, offset(1e-9));
        assertThat(new ProcessCpu.MachineIdle(1200, 1_000_000_000L, 2).busyPercentSince(start)).isZero();
        assertThat(new ProcessCpu.MachineIdle(0, 1_000_000_000L, 0).busyPercentSince(new ProcessCpu.MachineIdle(0, 0, 0)))
                .isZero();
    }

    @Test
    void stealPercentSince_isTheStolenShareOfElapsedTimeTimesCores() {
        ProcessCpu.MachineIdle start = new ProcessCpu.MachineIdle(1000, 0, 2, 70);
        // 2 cores for 1 s = 200 ticks of capacity; 6 ticks stolen -> 3 %
        assertThat(new ProcessCpu.MachineIdle(1050, 1_000_000_000L, 2, 76).stealPercentSince(start))
                .isCloseTo(3.0, offset(1e-9));
        assertThat(new ProcessCpu.MachineIdle(1050, 1_000_000_000L, 2, 70).stealPercentSince(start)).isZero();
        assertThat(new ProcessCpu.MachineIdle(0, 1_000_000_000L, 0, 5).stealPercentSince(new ProcessCpu.MachineIdle(0, 0, 0)))
                .isZero();
    }

    @Test
    void aReadingOfThisMachine_hasItsStealTicks_countingUpOrStill() {
        ProcessCpu.MachineIdle first = ProcessCpu.MachineIdle.now();
        ProcessCpu.MachineIdle second = ProcessCpu.MachineIdle.now();
        assertThat(first.stealTicks()).isNotNegative();
        assertThat(second.stealTicks()).isGreaterThanOrEqualTo(first.stealTicks());
        assertThat(second.stealPercentSince(first)).isBetween(0.0, 100.0);
    }
}
