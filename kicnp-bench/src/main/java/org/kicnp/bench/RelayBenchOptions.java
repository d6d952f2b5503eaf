package org.kicnp.bench;

import static java.util.Objects.requireNonNull;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import org.kicnp.gateway.Transport;

/**
 * How {@link GatewayRelayBench} runs.
 *
 * @param agentCounts the agent counts to run, in order (each even)
 * @param messageBytes bytes of each message on the wire (K-ICNP frame or MQTT PUBLISH packet)
 * @param rate the fixed offered load of the latency measurement, messages per second in total
 * @param outstanding the closed-loop messages outstanding in total, spread over the agents (at least 2 each)
 * @param clientThreads the client event loops
 * @param gatewayThreads the gateway's I/O threads; 0 keeps the gateway's default
 * @param gatewayInProcess run the gateway inside the bench's JVM, beside the clients, not in a process of its own
 * @param gatewayJavaOptions JVM options for the gateway's own process, after the launcher's
 * @param jitWarmup an untimed closed-loop run on each hub before the first measurement (zero: none)
 * @param mosquittoScript {@code scripts/mosquitto.sh}; empty skips Mosquitto
 * @param install whether the script may install Mosquitto with apt-get
 * @param transport the socket transport of the gateway and of the clients (both hubs' clients alike)
 */
record RelayBenchOptions(List<Integer> agentCounts, int messageBytes, int rate, Duration warmup, Duration throughputTime,
                         Duration latencyTime, int outstanding, int clientThreads, int gatewayThreads,
                         boolean gatewayInProcess, List<String> gatewayJavaOptions, Duration jitWarmup,
                         Optional<Path> mosquittoScript,
                         boolean install, Transport transport) {
    RelayBenchOptions {
        agentCounts = List.copyOf(agentCounts);
        gatewayJavaOptions = List.copyOf(gatewayJavaOptions);
        requireNonNull(warmup, "warmup");
        requireNonNull(throughputTime, "throughputTime");
        requireNonNull(latencyTime, "latencyTime");
        requireNonNull(jitWarmup, "jitWarmup");
        requireNonNull(mosquittoScript, "mosquittoScript");
        requireNonNull(transport, "transport");
        if (agentCounts.isEmpty() || agentCounts.stream().anyMatch(n -> n < 2 || n % 2 != 0)) {
            throw new IllegalArgumentException("Agent counts must be even numbers of 2 or more, not " + agentCounts + ".");
        }
        if (rate < 1 || outstanding < 1 || clientThreads < 1 || gatewayThreads < 0 || messageBytes < 64) {
            throw new IllegalArgumentException("Need a rate, outstanding messages and client threads of 1 or more and "
                    + "messages of 64 bytes or more.");
        }
    }

    /** The closed-loop window of each agent. */
    int windowFor(int agents) {
        return Math.max(2, outstanding / agents);
    }
}
