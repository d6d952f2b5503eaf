package org.kicnp.bench;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.concurrent.Callable;
import org.kicnp.gateway.Transport;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code ./kicnp bench gateway}: runs {@link GatewayRelayBench} and prints its conditions, its table and, as the
 * last line, one JSON object with the figures.
 */
@Command(name = "gateway",
        mixinStandardHelpOptions = true,
        description = {
            "Many agents relaying ~200-byte messages to each other through the K-ICNP gateway, then through Mosquitto",
            "(started by scripts/mosquitto.sh, which installs it with apt-get when missing); each hub in its own process,",
            "the same clients in this JVM for both: max throughput (closed loop) and p50/p99/p99.9 latency at a fixed",
            "offered load (open loop).",
            "The last line of output is one JSON object with the figures."
        })
final class GatewayRelayCommand implements Callable<Integer> {
    private static final int FLOOR_HOPS = 50_000;

    @Spec
    CommandSpec spec;

    @Option(names = "--agents", split = ",", defaultValue = "100,1000",
            description = "Agent counts to run, in order (default: ${DEFAULT-VALUE}).")
    List<Integer> agents;

    @Option(names = "--message-bytes", defaultValue = "200",
            description = "Bytes of each message on the wire (default: ${DEFAULT-VALUE}).")
    int messageBytes;

    @Option(names = "--rate", defaultValue = "50000",
            description = "Offered load of the latency run, messages per second in total (default: ${DEFAULT-VALUE}).")
    int rate;

    @Option(names = "--warmup", defaultValue = "2", description = "Warm-up seconds before each measurement (default: ${DEFAULT-VALUE}).")
    int warmupSeconds;

    @Option(names = "--jit-warmup", defaultValue = "20",
            description = "Seconds of an untimed closed-loop run on each hub (with the first agent count), followed "
                    + "by 5 s of the open loop, before the first measurement, so the JIT has compiled the gateway and "
                    + "the clients; on a loaded machine the compiler gets little CPU (default: ${DEFAULT-VALUE}; 0: none).")
    int jitWarmupSeconds;

    @Option(names = "--seconds", defaultValue = "5",
            description = "Seconds of each throughput and each latency measurement (default: ${DEFAULT-VALUE}).")
    int seconds;

    @Option(names = "--outstanding", defaultValue = "8192",
            description = "Closed-loop messages outstanding in total, spread over the agents (default: ${DEFAULT-VALUE}).")
    int outstanding;

    @Option(names = "--client-threads", defaultValue = "2", description = "Client event loops (default: ${DEFAULT-VALUE}).")
    int clientThreads;

    @Option(names = "--gateway-threads", defaultValue = "1",
            description = "The gateway's I/O threads (default: ${DEFAULT-VALUE}, as Mosquitto's one thread; 0: the "
                    + "gateway's own default of one per core, as `kicnp serve` runs it). With its own process on two "
                    + "cores shared with the clients, one thread gave the lower p99 at 1,000 agents in 8 of 9 "
                    + "alternating pairs: a relay between two loops costs a hand-off and often a wake-up "
                    + "(docs/benchmarks.md, round 4).")
    int gatewayThreads;

    @Option(names = "--transport", defaultValue = "auto", paramLabel = "NAME",
            description = "Socket transport of the gateway and of the clients (the same for both hubs' clients): "
                    + "auto (default: the best that works here, io_uring, then epoll, then nio), io_uring, epoll or "
                    + "nio.")
    String transport;

    @Option(names = "--gateway-in-process",
            description = "Run the gateway inside this JVM, beside the clients (their garbage collections and "
                    + "compilations then stall it too), instead of in a JVM of its own as `kicnp serve` runs it.")
    boolean gatewayInProcess;

    @Option(names = "--gateway-java-opts", paramLabel = "OPTS", defaultValue = "",
            description = "JVM options of the gateway's own process, space-separated, after those the launcher gives "
                    + "`kicnp serve` (default: none, the JVM's default collector and heap sizing).")
    String gatewayJavaOpts;

    @Option(names = "--no-mosquitto", description = "Measure K-ICNP alone.")
    boolean noMosquitto;

    @Option(names = "--no-install", description = "Never install Mosquitto; skip it (with a note) when it is missing.")
    boolean noInstall;

    @Option(names = "--mosquitto-script", description = "The broker script (default: scripts/mosquitto.sh of this tree).")
    Optional<Path> script;

    @Override public Integer call() throws Exception {
        if (seconds < 1 || warmupSeconds < 0 || jitWarmupSeconds < 0) {
            throw new ParameterException(spec.commandLine(),
                    "Need --seconds of 1 or more, and --warmup and --jit-warmup of 0 or more.");
        }
        quietGatewayLog();
        Optional<Path> mosquitto = noMosquitto ? Optional.empty() : script.or(MosquittoBroker::defaultScript);
        if (!noMosquitto && mosquitto.isEmpty()) {
            throw new ParameterException(spec.commandLine(), "Cannot find scripts/mosquitto.sh; give --mosquitto-script.");
        }
        RelayBenchOptions o;
        try {
            o = new RelayBenchOptions(agents, messageBytes, rate, Duration.ofSeconds(warmupSeconds),
                    Duration.ofSeconds(seconds), Duration.ofSeconds(seconds), outstanding, clientThreads,
                    gatewayThreads, gatewayInProcess, gatewayJavaOpts.isBlank() ? List.of()
                    : List.of(gatewayJavaOpts.strip().split("\\s+")), Duration.ofSeconds(jitWarmupSeconds), mosquitto,
                    !noInstall, Transport.parse(transport).requireAvailable());
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        out.print(RelayReport.preamble(o, noMosquitto ? "" : MosquittoBroker.version()));
        out.flush();
        List<RelayRun> runs = GatewayRelayBench.run(o, line -> {
            err.println(line);
            err.flush();
        });
        // Measured after the runs, so its socket calls cannot change what the JIT made of the clients' (with nio).
        OptionalDouble hop = loopbackHop(o.messageBytes(), err);
        out.println();
        out.print(RelayReport.table(runs, o.rate()));
        out.println();
        hop.ifPresent(h -> out.print(RelayReport.floor(h, o)));
        out.println(RelayReport.json(runs, o, hop));
        out.flush();
        return 0;
    }

    /** {@link LoopbackHop} over {@value #FLOOR_HOPS} hops; empty (said on {@code err}) when it cannot be measured. */
    private static OptionalDouble loopbackHop(int bytes, PrintWriter err) {
        try {
            return OptionalDouble.of(LoopbackHop.cpuMicros(bytes, FLOOR_HOPS));
        } catch (IOException e) {
            err.println("The loopback hop could not be measured: " + e.getMessage());
            return OptionalDouble.empty();
        }
    }

    /** The gateway logs every connection at INFO; a thousand of them would bury the table. */
    private static void quietGatewayLog() {
        if (System.getProperty("org.slf4j.simpleLogger.log.org.kicnp.gateway") == null) {
            System.setProperty("org.slf4j.simpleLogger.log.org.kicnp.gateway", "warn");
        }
    }
}
