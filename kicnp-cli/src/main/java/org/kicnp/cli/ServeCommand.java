package org.kicnp.cli;

import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.kicnp.cli.platform.Platform;
import org.kicnp.cli.platform.PlatformConfig;
import org.kicnp.gateway.Transport;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code kicnp serve KB_DIR}: runs the platform — durable knowledge base, inference engine, gateway and editor —
 * until interrupted (SIGINT stops it cleanly through a shutdown hook).
 */
@Command(name = "serve", mixinStandardHelpOptions = true,
        description = "Run the platform on a knowledge-base directory: inference engine, gateway for the agents, "
                + "knowledge editor, event log.")
public final class ServeCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "KB_DIR", description = "The knowledge-base directory (its *.xml files).")
    Path kbDir;

    @Option(names = "--gateway-port", defaultValue = "" + PlatformConfig.DEFAULT_GATEWAY_PORT, description = "Port of the agents' gateway (loopback). Default: ${DEFAULT-VALUE}.")
    int gatewayPort;

    @Option(names = "--http-port", defaultValue = "8080", description = "Port of the knowledge editor (loopback). Default: ${DEFAULT-VALUE}.")
    int httpPort;

    @Option(names = "--agents", paramLabel = "FILE", description = "Agent tokens (NAME.token = …). Default: KB_DIR/.kicnp/agents.properties, generated on first start.")
    Path agents;

    @Option(names = "--editor-password-file", paramLabel = "FILE", description = "The editor's password. Default: KB_DIR/.kicnp/editor-password, generated when missing.")
    Path passwordFile;

    @Option(names = "--event-log", paramLabel = "FILE", description = "Event log (JSON lines). Default: KB_DIR/.kicnp/logs/events-TIME.jsonl.")
    Path eventLog;

    @Option(names = "--transport", defaultValue = "auto", paramLabel = "NAME",
            description = "The gateway's socket transport: auto (default: the best that works here, io_uring, then "
                    + "epoll, then nio), io_uring, epoll or nio.")
    String transport;

    @Option(names = "--listen", paramLabel = "HOST:PORT",
            description = "Also let agents on other machines (robots on the lab's network) connect, at HOST:PORT "
                    + "(e.g. 0.0.0.0:7778; port 0: any free port, printed at start), over TLS with --tls-keystore. The gateway's loopback port stays for this "
                    + "machine's agents and tools. Default: loopback only.")
    String listen;

    @Option(names = "--tls-keystore", paramLabel = "FILE",
            description = "The server's key and certificate for --listen: a PKCS12 or JKS keystore, as keytool "
                    + "-genkeypair makes (see docs/deployment.md).")
    Path tlsKeystore;

    @Option(names = "--tls-password-file", paramLabel = "FILE",
            description = "The keystore's password: the file's first line.")
    Path tlsPasswordFile;

    @Option(names = "--plaintext-listen",
            description = "Let --listen use plain TCP, without TLS: the agents' tokens and every message then cross "
                    + "the network readable by anyone on it. Only on a network you trust entirely.")
    boolean plaintextListen;

    @Spec
    CommandSpec spec;

    @Override public Integer call() throws InterruptedException {
        Transport t;
        try {
            t = Transport.parse(transport);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        PlatformConfig config = PlatformConfig.of(kbDir).withGatewayPort(gatewayPort).withHttpPort(Optional.of(httpPort))
                .withAgentsFile(Optional.ofNullable(agents)).withEditorPasswordFile(Optional.ofNullable(passwordFile))
                .withEventLog(Optional.ofNullable(eventLog)).withGatewayTransport(t).withAgentListener(agentListener());
        Platform platform = Platform.start(config);
        printBanner(platform, plaintextListen);
        if (plaintextListen) {
            System.err.println("Warning: agents connecting at " + listen + " use plain TCP (--plaintext-listen): their "
                    + "tokens and messages cross the network readable by anyone on it.");
        }
        CountDownLatch stopped = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            platform.close();
            stopped.countDown();
        }, "kicnp-serve-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        stopped.await();
        return 0;
    }

    /** The further address of {@code --listen}, checked: TLS unless plain TCP is asked for in so many words. */
    private Optional<PlatformConfig.AgentListener> agentListener() {
        if (listen == null) {
            if (tlsKeystore != null || tlsPasswordFile != null || plaintextListen) {
                throw new ParameterException(spec.commandLine(), "--tls-keystore, --tls-password-file and "
                        + "--plaintext-listen are options of --listen HOST:PORT, which was not given.");
            }
            return Optional.empty();
        }
        GatewayAddress address;
        try {
            address = GatewayAddress.parse(listen, "--listen", 0);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        if (plaintextListen) {
            if (tlsKeystore != null) {
                throw new ParameterException(spec.commandLine(), "--plaintext-listen and --tls-keystore exclude each "
                        + "other: choose TLS or plain TCP for --listen.");
            }
            return Optional.of(new PlatformConfig.AgentListener(address.host(), address.port(), Optional.empty()));
        }
        if (tlsKeystore == null || tlsPasswordFile == null) {
            throw new ParameterException(spec.commandLine(), "--listen " + listen + " lets other machines connect, "
                    + "so it needs TLS: give --tls-keystore FILE and --tls-password-file FILE (docs/deployment.md "
                    + "says how to make them), or --plaintext-listen on a network you trust entirely.");
        }
        try {
            return Optional.of(new PlatformConfig.AgentListener(address.host(), address.port(),
                    Optional.of(TlsFiles.server(tlsKeystore, tlsPasswordFile))));
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
    }

    static void printBanner(Platform platform) {
        printBanner(platform, false);
    }

    /** @param plain whether the further address for other machines ({@code --listen}) is plain TCP */
    static void printBanner(Platform platform, boolean plain) {
        System.out.println("K-ICNP serving " + platform.kb().size() + " frames.");
        System.out.println("  gateway:  127.0.0.1:" + platform.gatewayPort() + " ("
                + platform.gatewayTransport().label() + " transport; agent tokens in " + platform.agentsFile() + ")");
        platform.agentListenerAddress().ifPresent(a -> System.out.println("  agents:   " + a.getHostString() + ":"
                + a.getPort() + " for other machines (" + (plain ? "plain TCP" : "TLS") + ")"));
        platform.editorPort().ifPresent(p -> System.out.println("  editor:   http://127.0.0.1:" + p + "/ (password in "
                + platform.editorPasswordFile().map(Path::toString).orElse("?") + ")"));
        System.out.println("  events:   " + platform.events().file());
        System.out.flush();
    }
}
