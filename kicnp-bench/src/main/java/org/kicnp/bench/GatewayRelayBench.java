package org.kicnp.bench;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;
import org.kicnp.gateway.GatewayServer;

/**
 * {@code ./kicnp bench gateway}: many agents relaying small messages to each other through a hub, K-ICNP's real
 * {@link GatewayServer} (in a process of its own, {@link GatewayProcess}, unless asked otherwise) against a Mosquitto
 * broker (its own process), with the same clients in this process. For each agent
 * count, each hub gets a closed-loop throughput run and an open-loop latency run at a fixed offered load.
 */
final class GatewayRelayBench {
    private static final Duration CONNECT_TIMEOUT = Duration.ofSeconds(60);
    /** The open-loop part of the JIT warm-up on each hub (see {@link #warm}). */
    static final Duration OPEN_WARMUP = Duration.ofSeconds(5);

    private GatewayRelayBench() {
    }

    /**
     * Runs every agent count on both hubs. The gateway and the broker are each started once, before the first
     * count, and stopped after the last.
     *
     * @param progress told what is being measured, for people watching
     */
    static List<RelayRun> run(RelayBenchOptions o, Consumer<String> progress) throws IOException, InterruptedException {
        int most = Collections.max(o.agentCounts());
        MosquittoBroker broker = null;
        String brokerNote = "Mosquitto skipped (--no-mosquitto).";
        if (o.mosquittoScript().isPresent()) {
            try {
                progress.accept("Starting Mosquitto with " + o.mosquittoScript().get() + " ...");
                broker = MosquittoBroker.start(o.mosquittoScript().get(), o.install());
            } catch (IllegalStateException e) {
                brokerNote = "Mosquitto not measured: " + e.getMessage();
                progress.accept(brokerNote);
            }
        }
        try (KicnpHub gateway = o.gatewayInProcess() ? InProcessGateway.start(most, o.gatewayThreads(), o.transport())
                : GatewayProcess.start(most, o.gatewayThreads(), o.transport(), o.gatewayJavaOptions())) {
            progress.accept("K-ICNP gateway on " + gateway.address() + ", " + gateway.describe() + ".");
            if (!o.jitWarmup().isZero()) {
                // Untimed: the JIT compiles the gateway's and both clients' hot paths before anything is measured
                // (Mosquitto is native and needs no such start).
                int n = o.agentCounts().get(0);
                progress.accept("Warming up the JIT for " + o.jitWarmup().toSeconds() + " s per hub (not measured) ...");
                warm(new KicnpRelayClient(o.messageBytes()), gateway.address(), n, o);
                if (broker != null) {
                    warm(new MqttRelayClient(o.messageBytes()), broker.address(), n, o);
                }
            }
            List<RelayRun> runs = new ArrayList<>();
            for (int agents : o.agentCounts()) {
                progress.accept("K-ICNP gateway, " + agents + " agents ...");
                long shedBefore = gateway.shed();
                HubFigures kicnp = measure(new KicnpRelayClient(o.messageBytes()), gateway.address(), agents, o,
                        () -> gateway.shed() - shedBefore, gateway::cpuNanos);
                progress.accept("  " + gateway.metrics());
                Optional<HubFigures> mqtt = Optional.empty();
                Optional<String> note = broker == null ? Optional.of(brokerNote) : Optional.empty();
                if (broker != null) {
                    progress.accept("Mosquitto, " + agents + " agents ...");
                    MosquittoBroker b = broker;
                    mqtt = Optional.of(measure(new MqttRelayClient(o.messageBytes()), broker.address(), agents, o,
                            () -> 0L, clients -> b.cpuNanos()));
                }
                runs.add(new RelayRun(agents, o.windowFor(agents), kicnp, mqtt, note));
            }
            return runs;
        } finally {
            if (broker != null) {
                broker.close();
            }
        }
    }

    private static HubFigures measure(RelayClient client, InetSocketAddress hub, int agents, RelayBenchOptions o,
                                      java.util.function.LongSupplier shed,
                                      java.util.function.LongUnaryOperator hubCpu) throws InterruptedException {
        try (RelayDriver d = RelayDriver.connect(client, hub, agents, o.clientThreads(), o.transport(),
                CONNECT_TIMEOUT)) {
            RelayDriver.Throughput t = d.throughput(o.windowFor(agents), o.warmup(), o.throughputTime(), hubCpu);
            LatencyFigures latency = d.latency(o.rate(), o.warmup(), o.latencyTime(), hubCpu);
            return new HubFigures(t.msgsPerSecond(), latency, shed.getAsLong(), t.hubCpuMicrosPerMsg(),
                    t.clientCpuMicrosPerMsg());
        }
    }

    /**
     * The untimed JIT warm-up: the closed loop for {@code --jit-warmup}, then the open loop at the offered rate for
     * {@link #OPEN_WARMUP}, so the open loop's own paths (the ticks, single-message reads and writes, the gateway's
     * scheduled tasks) are compiled too; before, they first ran two seconds before the measured window, and their
     * compilations and deoptimisations fell next to or into it.
     */
    private static void warm(RelayClient client, InetSocketAddress hub, int agents, RelayBenchOptions o)
            throws InterruptedException {
        try (RelayDriver d = RelayDriver.connect(client, hub, agents, o.clientThreads(), o.transport(),
                CONNECT_TIMEOUT)) {
            d.throughput(o.windowFor(agents), o.jitWarmup(), Duration.ofMillis(100), clients -> 0);
            d.latency(o.rate(), Duration.ZERO, OPEN_WARMUP, clients -> 0);
        }
    }
}
