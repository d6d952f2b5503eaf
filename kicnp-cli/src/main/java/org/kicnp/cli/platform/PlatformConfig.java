package org.kicnp.cli.platform;

import static java.util.Objects.requireNonNull;

import java.nio.file.Path;
import io.netty.handler.ssl.SslContext;
import java.util.Optional;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.Transport;

/**
 * How to start a {@link Platform}: the knowledge-base directory, the gateway and editor ports (0 = any free port,
 * the editor may be turned off), the agent file and editor password file (generated under the directory's
 * {@code .kicnp/} when absent), the event log file (default {@code .kicnp/logs/events-TIME.jsonl}) and the gateway's
 * socket transport (default: the best that works here, {@link Transport#best()}), and a further address of the
 * gateway for agents on other machines ({@link AgentListener}, none by default).
 */
public record PlatformConfig(Path kbDir, int gatewayPort, Optional<Integer> httpPort, Optional<Path> agentsFile,
                             Optional<Path> editorPasswordFile, Optional<Path> eventLog,
                             Transport gatewayTransport, Optional<AgentListener> agentListener) {
    public static final int DEFAULT_GATEWAY_PORT = GatewayConfig.DEFAULT_PORT;
    public static final int DEFAULT_HTTP_PORT = 8080;

    public PlatformConfig {
        requireNonNull(kbDir, "kbDir");
        requireNonNull(httpPort, "httpPort");
        requireNonNull(agentsFile, "agentsFile");
        requireNonNull(editorPasswordFile, "editorPasswordFile");
        requireNonNull(eventLog, "eventLog");
        requireNonNull(gatewayTransport, "gatewayTransport");
        requireNonNull(agentListener, "agentListener");
    }

    /**
     * A further address of the gateway, for agents on other machines (robots on the lab's network): {@code host:port}
     * with TLS on {@code tls}, or plain TCP when it is empty (only when asked for in so many words). The gateway's
     * first address stays on loopback for the platform's own agents and the tools on this machine.
     */
    public record AgentListener(String host, int port, Optional<SslContext> tls) {
        public AgentListener {
            requireNonNull(host, "host");
            requireNonNull(tls, "tls");
        }
    }

    public static PlatformConfig of(Path kbDir) {
        return new PlatformConfig(kbDir, DEFAULT_GATEWAY_PORT, Optional.of(DEFAULT_HTTP_PORT), Optional.empty(),
                Optional.empty(), Optional.empty(), Transport.best(), Optional.empty());
    }

    /** Any free ports: for tests and the headless replay. */
    public PlatformConfig withEphemeralPorts() {
        return new PlatformConfig(kbDir, 0, httpPort.map(p -> 0), agentsFile, editorPasswordFile, eventLog,
                gatewayTransport, agentListener);
    }

    public PlatformConfig withGatewayPort(int port) {
        return new PlatformConfig(kbDir, port, httpPort, agentsFile, editorPasswordFile, eventLog, gatewayTransport,
                agentListener);
    }

    public PlatformConfig withHttpPort(Optional<Integer> port) {
        return new PlatformConfig(kbDir, gatewayPort, port, agentsFile, editorPasswordFile, eventLog,
                gatewayTransport, agentListener);
    }

    public PlatformConfig withAgentsFile(Optional<Path> file) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, file, editorPasswordFile, eventLog, gatewayTransport,
                agentListener);
    }

    public PlatformConfig withEditorPasswordFile(Optional<Path> file) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, agentsFile, file, eventLog, gatewayTransport,
                agentListener);
    }

    public PlatformConfig withGatewayTransport(Transport transport) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, agentsFile, editorPasswordFile, eventLog, transport,
                agentListener);
    }

    public PlatformConfig withAgentListener(Optional<AgentListener> listener) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, agentsFile, editorPasswordFile, eventLog,
                gatewayTransport, listener);
    }

    public PlatformConfig withEventLog(Optional<Path> file) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, agentsFile, editorPasswordFile, file,
                gatewayTransport, agentListener);
    }
}
