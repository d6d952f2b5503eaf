package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class LoopbackHopTest {
    @Test
    void aHopOfAMessage_costsSomeCpu_andCarriesItsBytes() throws Exception {
        double micros = LoopbackHop.cpuMicros(200, 2_000);

        // A hop is at least one system call each way: more than nothing, and far less than a millisecond.
        assertThat(micros).isGreaterThan(0.0).isLessThan(1_000.0);
    }

    @Test
    void noBytesOrNoHops_isRefused() {
        assertThatThrownBy(() -> LoopbackHop.cpuMicros(0, 10)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("at least one byte");
        assertThatThrownBy(() -> LoopbackHop.cpuMicros(200, 0)).isInstanceOf(IllegalArgumentException.class);
    }
}
