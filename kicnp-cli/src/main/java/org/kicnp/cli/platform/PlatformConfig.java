package org.kicnp.cli.platform;

import static java.util.Objects.requireNonNull;

import java.nio.file.Path;
import java.util.Optional;

/**
 * How to start a {@link Platform}: the knowledge-base directory, the gateway and editor ports (0 = any free port,
 * the editor may be turned off), the agent file and editor password file (generated under the directory's
 * {@code .kicnp/} when absent), and the event log file (default {@code .kicnp/logs/events-TIME.jsonl}).
 */
public record PlatformConfig(Path kbDir, int gatewayPort, Optional<Integer> httpPort, Optional<Path> agentsFile,
                             Optional<Path> editorPasswordFile, Optional<Path> eventLog) {
    public static final int DEFAULT_GATEWAY_PORT = 7777;
    public static final int DEFAULT_HTTP_PORT = 8080;

    public PlatformConfig {
        requireNonNull(kbDir, "kbDir");
        requireNonNull(httpPort, "httpPort");
        requireNonNull(agentsFile, "agentsFile");
        requireNonNull(editorPasswordFile, "editorPasswordFile");
        requireNonNull(eventLog, "eventLog");
    }

    public static PlatformConfig of(Path kbDir) {
        return new PlatformConfig(kbDir, DEFAULT_GATEWAY_PORT, Optional.of(DEFAULT_HTTP_PORT), Optional.empty(),
                Optional.empty(), Optional.empty());
    }

    /** Any free ports: for tests and the headless replay. */
    public PlatformConfig withEphemeralPorts() {
        return new PlatformConfig(kbDir, 0, httpPort.map(p -> 0), agentsFile, editorPasswordFile, eventLog);
    }

    public PlatformConfig withGatewayPort(int port) {
        return new PlatformConfig(kbDir, port, httpPort, agentsFile, editorPasswordFile, eventLog);
    }

    public PlatformConfig withHttpPort(Optional<Integer> port) {
        return new PlatformConfig(kbDir, gatewayPort, port, agentsFile, editorPasswordFile, eventLog);
    }

    public PlatformConfig withAgentsFile(Optional<Path> file) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, file, editorPasswordFile, eventLog);
    }

    public PlatformConfig withEditorPasswordFile(Optional<Path> file) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, agentsFile, file, eventLog);
    }

    public PlatformConfig withEventLog(Optional<Path> file) {
        return new PlatformConfig(kbDir, gatewayPort, httpPort, agentsFile, editorPasswordFile, file);
    }
}
