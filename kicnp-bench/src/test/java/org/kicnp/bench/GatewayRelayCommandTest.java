package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kicnp.gateway.Transport;
import picocli.CommandLine;

/** {@code bench gateway} end to end on a tiny configuration: real gateway, real sockets, the real broker if any. */
class GatewayRelayCommandTest {
    private static final List<String> RUN_KEYS = List.of("agents", "kicnp_msgs_per_s", "mosquitto_msgs_per_s",
            "ratio", "kicnp_p99_ms_at_50k");

    @Test
    void gateway_kicnpAlone_printsTableThenJsonWithPositiveFigures() throws Exception {
        Output run = run("gateway", "--agents", "10", "--seconds", "1", "--warmup", "1", "--jit-warmup", "0", "--rate", "2000",
                "--no-mosquitto");

        assertThat(run.code()).as(run.err()).isZero();
        JsonNode r = lastJson(run.out()).get("runs").get(0);
        assertThat(RUN_KEYS).allSatisfy(k -> assertThat(r.has(k)).as(k).isTrue());
        assertThat(r.get("agents").asInt()).isEqualTo(10);
        assertThat(r.get("kicnp_msgs_per_s").asDouble()).isPositive();
        assertThat(r.get("kicnp_p99_ms_at_50k").asDouble()).isPositive();
        assertThat(r.get("kicnp_lost_at_50k").asLong()).isZero();
        assertThat(r.get("mosquitto_msgs_per_s").isNull()).isTrue();
        assertThat(r.get("ratio").isNull()).isTrue();
        assertThat(run.out()).contains("K-ICNP", "coordinated omission",
                Runtime.getRuntime().availableProcessors() + " cores", "gateway: a JVM of its own");
        assertThat(lastJson(run.out()).get("gateway").asText()).isEqualTo("own_process");
        // auto: the best transport that works here, named in the header and the JSON
        assertThat(lastJson(run.out()).get("transport").asText()).isEqualTo(Transport.best().label());
        assertThat(run.out()).contains("socket transport (gateway and clients): " + Transport.best().label());
        // the kernel's floor: a measured hop, and the busy share two of them per message set at the offered rate
        double hop = lastJson(run.out()).get("loopback_hop_us").asDouble();
        assertThat(hop).isPositive();
        assertThat(lastJson(run.out()).get("floor_busy_pct_at_rate").asDouble()).isCloseTo(
                2 * hop * 2_000 / 1e6 / Runtime.getRuntime().availableProcessors() * 100, within(0.1));
        assertThat(run.out()).contains("kernel floor: one loopback TCP hop of 200 bytes");
    }

    @Test
    void gateway_withJavaNio_runsGatewayAndClientsOnIt() throws Exception {
        Output run = run("gateway", "--agents", "4", "--seconds", "1", "--warmup", "0", "--jit-warmup", "0", "--rate", "1000",
                "--no-mosquitto", "--transport", "nio");

        assertThat(run.code()).as(run.err()).isZero();
        JsonNode json = lastJson(run.out());
        assertThat(json.get("transport").asText()).isEqualTo("nio");
        assertThat(json.get("runs").get(0).get("kicnp_msgs_per_s").asDouble()).isPositive();
        assertThat(json.get("runs").get(0).get("kicnp_lost_at_50k").asLong()).isZero();
        // the open loop's cost: the gateway's own process spent CPU time, and the machine was busy but not over 100 %
        assertThat(json.get("runs").get(0).get("kicnp_hub_cpu_us_per_msg_at_50k").asDouble()).isNotNegative();
        assertThat(json.get("runs").get(0).get("kicnp_busy_pct_at_50k").asDouble()).isPositive()
                .isLessThanOrEqualTo(100);
        assertThat(json.get("runs").get(0).get("mosquitto_busy_pct_at_50k").isNull()).isTrue();
        assertThat(json.get("runs").get(0).get("kicnp_steal_pct_at_50k").asDouble()).isBetween(0.0, 100.0);
        assertThat(json.get("runs").get(0).get("mosquitto_steal_pct_at_50k").isNull()).isTrue();
        assertThat(run.out()).contains("busy = the share of the whole machine").contains("steal = the share the hypervisor");
    }

    @Test
    void gateway_unknownTransport_isAUsageErrorListingTheChoices() {
        Output run = run("gateway", "--agents", "4", "--no-mosquitto", "--transport", "carrier-pigeon");

        assertThat(run.code()).isEqualTo(2);
        assertThat(run.err()).contains("carrier-pigeon", "auto, io_uring, epoll, nio");
    }

    @Test
    void gateway_inProcess_runsTheGatewayInThisJvmAndSaysSo() throws Exception {
        Output run = run("gateway", "--agents", "4", "--seconds", "1", "--warmup", "0", "--jit-warmup", "0", "--rate", "1000",
                "--no-mosquitto", "--gateway-in-process");

        assertThat(run.code()).as(run.err()).isZero();
        JsonNode json = lastJson(run.out());
        assertThat(json.get("gateway").asText()).isEqualTo("in_process");
        assertThat(json.get("runs").get(0).get("kicnp_msgs_per_s").asDouble()).isPositive();
        assertThat(run.out()).contains("gateway: in this JVM, beside the clients");
    }

    @Test
    void gateway_withMosquitto_measuresBothAndGivesTheRatio() throws Exception {
        assumeTrue(MosquittoBroker.installed(),
                "Mosquitto is not installed (apt-get install mosquitto): the side-by-side run is skipped.");

        Output run = run("gateway", "--agents", "10", "--seconds", "1", "--warmup", "1", "--jit-warmup", "0", "--rate", "2000",
                "--no-install");

        assertThat(run.code()).as(run.err()).isZero();
        JsonNode r = lastJson(run.out()).get("runs").get(0);
        assertThat(RUN_KEYS).allSatisfy(k -> assertThat(r.get(k).isNumber()).as(k).isTrue());
        assertThat(r.get("kicnp_msgs_per_s").asDouble()).isPositive();
        assertThat(r.get("mosquitto_msgs_per_s").asDouble()).isPositive();
        assertThat(r.get("ratio").asDouble()).isCloseTo(r.get("kicnp_msgs_per_s").asDouble()
                / r.get("mosquitto_msgs_per_s").asDouble(), org.assertj.core.data.Percentage.withPercentage(1));
        assertThat(r.get("mosquitto_p99_ms_at_50k").asDouble()).isPositive();
        assertThat(run.out()).contains("Mosquitto", "ratio K-ICNP / Mosquitto");
    }

    @Test
    void gateway_oddAgentCount_isAUsageError() {
        Output run = run("gateway", "--agents", "3", "--no-mosquitto");

        assertThat(run.code()).isEqualTo(2);
        assertThat(run.err()).contains("even");
    }

    private static JsonNode lastJson(String out) throws Exception {
        List<String> lines = out.lines().toList();
        return new ObjectMapper().readTree(lines.get(lines.size() - 1));
    }

    private record Output(int code, String out, String err) {
    }

    private static Output run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = new CommandLine(new BenchMain()).setOut(new PrintWriter(out)).setErr(new PrintWriter(err))
                .execute(args);
        return new Output(code, out.toString(), err.toString());
    }
}
