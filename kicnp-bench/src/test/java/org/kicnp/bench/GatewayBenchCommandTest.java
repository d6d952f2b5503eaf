package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class GatewayBenchCommandTest {

    @Test
    void json_givesEachPeerItsFiguresAndNullWhenSkipped() throws Exception {
        List<PingPongResult> results = List.of(
                new PingPongResult("K-ICNP gateway", 500, 64, 120, 480, 900, 7000.4, Optional.empty()),
                PingPongResult.skipped("Mosquitto (MQTT QoS 1)", 64, "Mosquitto is not installed."));

        JsonNode json = new ObjectMapper().readTree(GatewayBenchCommand.json(results));

        assertThat(json.get("round_trips").asInt()).isEqualTo(500);
        JsonNode kicnp = json.get("peers").get("k_icnp_gateway");
        assertThat(kicnp.get("p50_us").asLong()).isEqualTo(120);
        assertThat(kicnp.get("p99_us").asLong()).isEqualTo(480);
        assertThat(kicnp.get("round_trips_per_s").asDouble()).isEqualTo(7000);
        assertThat(json.get("peers").get("mosquitto_mqtt_qos_1").isNull()).isTrue();
    }
}
