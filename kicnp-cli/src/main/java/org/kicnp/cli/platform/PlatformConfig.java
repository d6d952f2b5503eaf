package org.kicnp.cli.platform;

import static java.util.Objects.requireNonNull;

import java.nio.file.Path;
import java.util.Optional;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.Transport;

/**
 * How to start a {@link Platform}: the knowledge-base directory, the gateway and editor ports (0 = any free port,
 * the editor may be turned off), the agent file and editor password file (generated under the directory's
 * {@code .kicnp/} when absent), the event log file (default {@code .kicnp/logs/events-TIME.jsonl}) and the gateway's
 * socket transport (default: the best that works here, {@link Transport#best()}).
 */
public record PlatformConfig(Path kbDir, int gatewayPort, Optional<Integer> httpPort, Optional<Path> agentsFile,
                             Optional<Path> editorPasswordFile, Optional<Path> eventLog,
                             Transport gatewayTransport) {
    public static final int DEFAULT_GATEWAY_PORT = GatewayConfig.DEFAULT_PORT;
    public static final int DEFAULT_HTTP_PORT = 8080;

    public PlatformConfig {
        requireNonNull(kbDir, "kbDir");
        requireNonNull(httpPort, "httpPort");
        requireNonNull(agentsFile, "agentsFile");
        requireNonNull(editorPasswordFile, "editorPasswordFile");
        requireNonNull(eventLog, "eventLog");
        requireNonNull(gatewayTransport, "gatewayTransport");
    }

    public static PlatformConfig of(Path kbDir) {
        return new PlatformConfig(kbDir, DEFAULT_GATEWAY_PORT, Optional.of(DEFAULT_HTTP_PORT), Optional.empty(),
                Optional.empty(), Optional.empty(), Transport.best());
    }

    /** Any free ports: for tests and the headless replay. */
    public PlatformConfig withEphemeralPorts() {
        return new PlatformConfig(kbDir, 0, httpPort.map(p -> 0), agentsFile, editorPasswordFile, eventLog,
                gatewayTransport);
    }

    public PlatformConfig withGatewayPort(int port) {
        return new PlatformConfig(kbDir, port, httpPort, agentsFile, editorPasswordFile, eventLog, gatewayTransport);
    }

    public PlatformConfig withHttpPort(Optional<Integer> port) {
        return new PlatformConfig(kbDir, gatewayPort, port, agentsFile, editorPasswordFile, eventLog, gatewayTransport);
    }

    public PlatformConfig withAgentsFile(Optional<Path> file) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, file, editorPasswordFile, eventLog, gatewayTransport);
    }

    public PlatformConfig withEditorPasswordFile(Optional<Path> file) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, agentsFile, file, eventLog, gatewayTransport);
    }

    public PlatformConfig withGatewayTransport(Transport transport) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, agentsFile, editorPasswordFile, eventLog, transport);
    }

    public PlatformConfig withEventLog(Optional<Path> file) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, agentsFile, editorPasswordFile, file, gatewayTransport);
    }
}
