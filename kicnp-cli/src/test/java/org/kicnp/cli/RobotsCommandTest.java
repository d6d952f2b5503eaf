package org.kicnp.cli;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.gateway.AgentDirectory;
import org.kicnp.gateway.FeedbackListener;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.GatewayServer;
import org.kicnp.protocol.AgentKind;
import picocli.CommandLine;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import static org.assertj.core.api.Assertions.assertThat;

/** {@code kicnp robots} against a real gateway on loopback, with the real simulator. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RobotsCommandTest {
    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(String... args) {
        CommandLine cl = new CommandLine(new Main());
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        return cl.execute(args);
    }

    @Test
    void robots_startsTheFourAgentsAgainstARunningServer_andStopsAfterTheGivenTime(@TempDir Path dir) throws Exception {
        AgentDirectory agents = AgentDirectory.empty();
        List<String> lines = new ArrayList<>();
        for (String robot : List.of("robovie", "pino", "scout", "aibo")) {
            agents = agents.with(robot, robot + "-secret", AgentKind.ROBOT);
            lines.add(robot + ".token = " + robot + "-secret");
        }
        Path tokens = Files.write(dir.resolve("agents.properties"), lines);
        KnowledgeBase kb = KnowledgeBase.create();
        GatewayConfig config = GatewayConfig.defaults().withPort(0);
        try (GatewayServer server = GatewayServer.start(config, agents, kb, FeedbackListener.NONE)) {
            CompletableFuture<Integer> exit = CompletableFuture.supplyAsync(() -> run("robots",
                    "--gateway", "127.0.0.1:" + server.port(), "--tokens", tokens.toString(), "--seed", "5", "--for", "4"));
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (server.registeredAgents().size() < 4 && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            assertThat(server.registeredAgents()).containsExactly("aibo", "pino", "robovie", "scout");
            assertThat(kb.contains("RobovieSay")).isTrue();

            assertThat(exit.get(30, TimeUnit.SECONDS)).isZero();
        }
        assertThat(out.toString()).contains("Agent 'scout' registered with 127.0.0.1:").contains("Robots stopped.");
        assertThat(err.toString()).doesNotContain("The simulator is gone");
        assertThat(kb.contains("signal_robovie_simulator")).as("a 'simulator exited' signal on a normal stop").isFalse();
    }

    @Test
    void robots_stoppedBySigterm_stopsTheAgentsAndTheSimulatorCleanly(@TempDir Path dir) throws Exception {
        AgentDirectory agents = AgentDirectory.empty();
        List<String> lines = new ArrayList<>();
        for (String robot : List.of("robovie", "pino", "scout", "aibo")) {
            agents = agents.with(robot, robot + "-secret", AgentKind.ROBOT);
            lines.add(robot + ".token = " + robot + "-secret");
        }
        Path tokens = Files.write(dir.resolve("agents.properties"), lines);
        Path output = dir.resolve("robots.out");
        KnowledgeBase kb = KnowledgeBase.create();
        try (GatewayServer server = GatewayServer.start(GatewayConfig.defaults().withPort(0), agents, kb,
                FeedbackListener.NONE)) {
            String java = ProcessHandle.current().info().command().orElse("java");
            Process robots = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"),
                    Main.class.getName(), "robots", "--gateway", "127.0.0.1:" + server.port(),
                    "--tokens", tokens.toString()).redirectErrorStream(true).redirectOutput(output.toFile()).start();
            try {
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(40);
                while (server.registeredAgents().size() < 4 && System.nanoTime() < deadline) {
                    Thread.sleep(20);
                }
                assertThat(server.registeredAgents()).hasSize(4);
                List<ProcessHandle> simulator = robots.descendants().toList();
                assertThat(simulator).isNotEmpty();

                robots.destroy(); // SIGTERM, as from kill or a service manager

                assertThat(robots.waitFor(20, TimeUnit.SECONDS)).isTrue();
                assertThat(Files.readString(output)).contains("Robots stopped.").doesNotContain("The simulator is gone");
                assertThat(simulator).noneMatch(ProcessHandle::isAlive);
            } finally {
                robots.descendants().forEach(ProcessHandle::destroyForcibly);
                robots.destroyForcibly();
            }
        }
    }

    @Test
    void robots_stoppedBySigtermDuringStartUp_stopsTheSimulatorAndTheAgentStartedSoFar(@TempDir Path dir) throws Exception {
        Path tokens = Files.write(dir.resolve("agents.properties"),
                List.of("robovie.token = a", "pino.token = b", "scout.token = c", "aibo.token = d"));
        Path output = dir.resolve("robots.out");
        // The first agent waits for its welcome from a server that never answers, so start-up cannot finish.
        try (SilentServer silent = new SilentServer()) {
            String java = ProcessHandle.current().info().command().orElse("java");
            Process robots = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"),
                    Main.class.getName(), "robots", "--gateway", "127.0.0.1:" + silent.port(),
                    "--tokens", tokens.toString()).redirectErrorStream(true).redirectOutput(output.toFile()).start();
            try {
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(40);
                // The probe, then robovie's connection.
                while ((silent.accepted() < 2 || !Files.readString(output).contains("Simulator started"))
                        && System.nanoTime() < deadline) {
                    Thread.sleep(20);
                }
                assertThat(Files.readString(output)).contains("Simulator started");
                assertThat(silent.accepted()).isGreaterThanOrEqualTo(2);
                List<ProcessHandle> simulator = robots.descendants().toList();
                assertThat(simulator).isNotEmpty();

                robots.destroy(); // SIGTERM while robovie is still waiting to be registered

                assertThat(robots.waitFor(20, TimeUnit.SECONDS)).isTrue();
                assertThat(Files.readString(output)).contains("Robots stopped.")
                        .doesNotContain("The simulator is gone").doesNotContain("was not registered");
                assertThat(simulator).noneMatch(ProcessHandle::isAlive);
            } finally {
                robots.descendants().forEach(ProcessHandle::destroyForcibly);
                robots.destroyForcibly();
            }
        }
    }

    @Test
    void robots_whoseSimulatorDiesDuringStartUp_exitsWith1SayingSo_withoutWaitingForTheAgent(@TempDir Path dir)
            throws Exception {
        Path tokens = Files.write(dir.resolve("agents.properties"),
                List.of("robovie.token = a", "pino.token = b", "scout.token = c", "aibo.token = d"));
        // Robovie is still waiting to be registered by a server that never answers when the simulator dies.
        try (SilentServer silent = new SilentServer()) {
            CompletableFuture<Integer> exit = CompletableFuture.supplyAsync(() -> run("robots",
                    "--gateway", "127.0.0.1:" + silent.port(), "--tokens", tokens.toString()));
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while ((silent.accepted() < 2 || !out.toString().contains("Simulator started"))
                    && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            long pid = Long.parseLong(out.toString().replaceAll("(?s).*Simulator started \\(pid (\\d+),.*", "$1"));

            ProcessHandle.of(pid).orElseThrow().destroyForcibly();

            assertThat(exit.get(10, TimeUnit.SECONDS)).isEqualTo(1);
            assertThat(err.toString()).contains("The simulator is gone").doesNotContain("was not registered");
            assertThat(out.toString()).contains("Robots stopped.");
        }
    }

    @Test
    void robots_withAGatewayThatIsNotHostAndPort_exitsWith2SayingSo(@TempDir Path dir) throws Exception {
        Path tokens = Files.write(dir.resolve("agents.properties"), List.of("robovie.token = x"));

        assertThat(run("robots", "--gateway", "localhost:99999", "--tokens", tokens.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("--gateway 'localhost:99999' is not HOST:PORT with a port from 1 to 65535.");
    }

    @Test
    void robots_withATimeScaleOrDurationOutOfRange_exitsWith2BeforeStartingAnything(@TempDir Path dir) throws Exception {
        Path tokens = Files.write(dir.resolve("agents.properties"),
                List.of("robovie.token = a", "pino.token = b", "scout.token = c", "aibo.token = d"));

        assertThat(run("robots", "--tokens", tokens.toString(), "--time-scale", "5000")).isEqualTo(2);
        assertThat(run("robots", "--tokens", tokens.toString(), "--for", "-3")).isEqualTo(2);
        assertThat(run("robots", "--tokens", tokens.toString(), "--for", "NaN")).isEqualTo(2);
        assertThat(err.toString())
                .contains("--time-scale 5000.0 is outside 0..1000.")
                .contains("--for -3.0 is not a positive number of seconds.")
                .contains("--for NaN is not a positive number of seconds.");
        assertThat(out.toString()).doesNotContain("Simulator started");
    }

    @Test
    void robots_withoutATokenForARobot_exitsWith2NamingIt(@TempDir Path dir) throws Exception {
        Path tokens = Files.write(dir.resolve("agents.properties"), List.of("robovie.token = x", "pino.token = y"));

        assertThat(run("robots", "--tokens", tokens.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("has no 'scout.token'.");
    }

    @Test
    void robots_withNoAgentFile_orNoServerThere_saySoAtOnce_withoutStartingTheSimulator(@TempDir Path dir)
            throws Exception {
        assertThat(run("robots", "--tokens", dir.resolve("agents.properties").toString())).isEqualTo(2);
        assertThat(err.toString()).contains("There is no agent file '" + dir.resolve("agents.properties")
                + "'; give --tokens KB_DIR/.kicnp/agents.properties of the running server");

        Path tokens = Files.write(dir.resolve("agents.properties"),
                List.of("robovie.token = a", "pino.token = b", "scout.token = c", "aibo.token = d"));
        int port;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        assertThat(run("robots", "--gateway", "127.0.0.1:" + port, "--tokens", tokens.toString())).isEqualTo(1);
        assertThat(err.toString()).contains("No server answers at 127.0.0.1:" + port + " (Connection refused); start "
                + "one first (./kicnp serve KB_DIR)");
        assertThat(out.toString()).doesNotContain("Simulator started");
    }

    @Test
    void robots_byDefault_connectsToThePortServeListensOnByDefault() {
        CommandLine robots = new CommandLine(new RobotsCommand());
        robots.parseArgs();
        CommandLine serve = new CommandLine(new ServeCommand());
        serve.parseArgs("kb");

        String gateway = ((RobotsCommand) robots.getCommand()).gateway;

        assertThat(gateway).isEqualTo("127.0.0.1:" + ((ServeCommand) serve.getCommand()).gatewayPort);
    }

    @Test
    void robots_help_listsItsOptions() {
        assertThat(run("robots", "--help")).isZero();
        assertThat(out.toString()).contains("--gateway").contains("--tokens").contains("--seed").contains("--time-scale");
    }

    /** A loopback server that accepts connections and never answers them: an agent waits there for its welcome. */
    private static final class SilentServer implements AutoCloseable {
        private final ServerSocket server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        private final List<Socket> accepted = new CopyOnWriteArrayList<>();

        SilentServer() throws IOException {
            Thread.ofVirtual().start(() -> {
                try {
                    while (true) {
                        accepted.add(server.accept());
                    }
                } catch (IOException e) {
                    // closed by close()
                }
            });
        }

        int port() {
            return server.getLocalPort();
        }

        /** The number of connections accepted so far. */
        int accepted() {
            return accepted.size();
        }

        @Override public void close() throws IOException {
            server.close();
            for (Socket s : accepted) {
                s.close();
            }
        }
    }
}
