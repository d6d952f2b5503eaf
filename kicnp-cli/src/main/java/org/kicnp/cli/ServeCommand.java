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
                .withEventLog(Optional.ofNullable(eventLog)).withGatewayTransport(t);
        Platform platform = Platform.start(config);
        printBanner(platform);
        CountDownLatch stopped = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            platform.close();
            stopped.countDown();
        }, "kicnp-serve-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        stopped.await();
        return 0;
    }

    static void printBanner(Platform platform) {
        System.out.println("K-ICNP serving " + platform.kb().size() + " frames.");
        System.out.println("  gateway:  127.0.0.1:" + platform.gatewayPort() + " ("
                + platform.gatewayTransport().label() + " transport; agent tokens in " + platform.agentsFile() + ")");
        platform.editorPort().ifPresent(p -> System.out.println("  editor:   http://127.0.0.1:" + p + "/ (password in "
                + platform.editorPasswordFile().map(Path::toString).orElse("?") + ")"));
        System.out.println("  events:   " + platform.events().file());
        System.out.flush();
    }
}
