package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

class GatewayBenchTest {
    @Test
    void run_measuresKicnp_andMosquittoWhenInstalled_andTabulatesBoth() throws Exception {
        List<PingPongResult> results = GatewayBench.run(200, 64);

        assertThat(results).hasSize(2);
        PingPongResult kicnp = results.get(0);
        assertThat(kicnp.measured()).isTrue();
        assertThat(kicnp.roundTrips()).isEqualTo(200);
        assertThat(kicnp.p50Micros()).isPositive().isLessThanOrEqualTo(kicnp.p99Micros());
        assertThat(kicnp.roundTripsPerSecond()).isPositive();

        PingPongResult mqtt = results.get(1);
        assertThat(mqtt.measured()).isEqualTo(MosquittoPingPong.executable().isPresent());
        if (mqtt.measured()) {
            assertThat(mqtt.roundTrips()).isEqualTo(200);
        } else {
            assertThat(mqtt.note()).contains("Mosquitto is not installed (apt-get install mosquitto).");
        }
        String table = GatewayBench.table(results);
        assertThat(table.lines()).hasSize(3);
        assertThat(table).contains("K-ICNP gateway", "Mosquitto");
    }
}
