package org.kicnp.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.Properties;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.gateway.AgentDirectory;
import org.kicnp.gateway.FeedbackListener;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.GatewayServer;
import org.kicnp.gateway.Transport;

/**
 * The gateway process of {@code bench gateway} ({@link GatewayProcess} starts it): the real {@link GatewayServer}
 * with its default configuration on an ephemeral loopback port, authenticating the bench's agents by their tokens,
 * in a JVM of its own, as {@code kicnp serve} runs it and as Mosquitto runs in its own process.
 *
 * <p>Arguments: {@code AGENTS IO_THREADS TRANSPORT} (0 threads: the gateway's default of one per core; a transport
 * as {@link Transport#parse} reads it). It prints {@code port=N} on
 * standard output once it listens, then answers one line per command read from standard input: {@code shed} →
 * {@code shed=N}, {@code metrics} → {@code metrics=…}. It stops when standard input ends (the bench closed it or
 * died), so it never outlives the bench.
 */
public final class GatewayMain {
    private GatewayMain() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 3) {
            System.err.println("Usage: GatewayMain AGENTS IO_THREADS TRANSPORT");
            System.exit(2);
        }
        int agents = Integer.parseInt(args[0]);
        int ioThreads = Integer.parseInt(args[1]);
        GatewayConfig config = GatewayConfig.defaults().withPort(0).withTransport(Transport.parse(args[2]));
        if (ioThreads > 0) {
            config = config.withIoThreads(ioThreads);
        }
        PrintStream out = System.out;
        try (GatewayServer gateway = GatewayServer.start(config, directory(agents), KnowledgeBase.create(),
                FeedbackListener.NONE);
             BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8))) {
            out.println("port=" + gateway.port());
            out.flush();
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                switch (line.strip()) {
                    case "shed" -> out.println("shed=" + gateway.metrics().shed());
                    case "metrics" -> out.println("metrics=" + gateway.metrics());
                    default -> out.println("error=unknown command '" + line.strip() + "'");
                }
                out.flush();
            }
        }
    }

    /** The agent directory of the bench agents {@code a00000 ...}: each a user with its own token. */
    static AgentDirectory directory(int agents) {
        Properties p = new Properties();
        for (int k = 0; k < agents; k++) {
            String name = RelayAgent.nameOf(k);
            p.setProperty(name + ".token", KicnpRelayClient.TOKEN_PREFIX + name);
            p.setProperty(name + ".kinds", "user");
        }
        return AgentDirectory.of(p, "bench agents");
    }
}
