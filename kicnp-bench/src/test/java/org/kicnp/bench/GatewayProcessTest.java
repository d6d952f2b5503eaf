package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.kicnp.gateway.Transport;

/** The gateway in its own process: it comes up, authenticates and relays the bench agents, and stops when closed. */
class GatewayProcessTest {
    @ParameterizedTest
    @EnumSource(Transport.class)
    void start_relaysBetweenBenchAgents_onEachTransport_andStopsWhenClosed(Transport transport) throws Exception {
        assumeTrue(transport.isAvailable(), () -> transport.label() + " does not work here: "
                + transport.unavailabilityCause().orElse(""));
        GatewayProcess gateway = GatewayProcess.start(4, 1, transport, List.of());
        try {
            assertThat(gateway.isAlive()).isTrue();
            assertThat(gateway.pid()).isNotEqualTo(ProcessHandle.current().pid());
            try (RelayDriver d = RelayDriver.connect(new KicnpRelayClient(200), gateway.address(), 4, 1, transport,
                    Duration.ofSeconds(30))) {
                RelayDriver.Throughput t = d.throughput(4, Duration.ZERO, Duration.ofMillis(300), gateway::cpuNanos);
                assertThat(t.msgsPerSecond()).isPositive();
                assertThat(t.hubCpuMicrosPerMsg()).isPositive(); // the gateway process's own CPU time, from /proc
                LatencyFigures latency = d.latency(400, Duration.ZERO, Duration.ofMillis(500), gateway::cpuNanos);
                assertThat(latency.lost()).isZero();
                assertThat(latency.clientCpuMicrosPerMsg()).isPositive(); // the client loops' thread CPU time
                assertThat(latency.hubCpuMicrosPerMsg()).isNotNegative(); // /proc counts in 10 ms ticks: may be 0
                assertThat(latency.machineBusyPercent()).isPositive().isLessThanOrEqualTo(100);
            }
            assertThat(gateway.shed()).isZero();
            assertThat(gateway.metrics()).contains("connections=4");
        } finally {
            gateway.close();
        }
        assertThat(gateway.isAlive()).isFalse();
    }

    @Test
    void start_refusesAnAgentWithoutItsToken() throws Exception {
        try (GatewayProcess gateway = GatewayProcess.start(2, 1, Transport.best(), List.of())) {
            // Agents a00002 and a00003 are not in its directory: authentication fails and the connection closes.
            assertThatThrownBy(() -> RelayDriver.connect(new KicnpRelayClient(200), gateway.address(), 4, 1,
                    Transport.best(), Duration.ofSeconds(30)).close())
                    .isInstanceOf(IllegalStateException.class)
                    .hasMessageContaining("a0000");
        }
    }

    @Test
    void start_whenTheJvmRefusesAnOption_saysItDidNotStart() {
        assertThatThrownBy(() -> GatewayProcess.start(2, 1, Transport.best(), List.of("-XX:+NoSuchJvmOption")))
                .isInstanceOf(IllegalStateException.class)
                .hasMessageContaining("ended before it listened");
    }
}
