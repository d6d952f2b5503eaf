package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.netty.handler.ssl.SslContextBuilder;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.security.KeyStore;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.KeyManagerFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message.Command;

/**
 * docs/examples/python_agent.py, a robot agent written from docs/protocol.md alone, works against the gateway; when
 * Python's jsonschema is installed it also checks every message of the session against the published schemas.
 */
class PythonAgentTest {
    @Test
    void pythonRobotAgent_registersReportsAndCarriesOutACommand() throws Exception {
        assumeTrue(python(), "python3 is not installed");
        KnowledgeBase kb = KnowledgeBase.create();
        List<String> heard = new CopyOnWriteArrayList<>();
        AgentDirectory agents = AgentDirectory.empty().with("pyrobot", "py-token", AgentKind.ROBOT);
        try (GatewayServer server = GatewayServer.start(GatewayConfig.defaults().withPort(0), agents, kb,
                new GatewayEndToEndTest.Recorder(heard))) {
            Process p = new ProcessBuilder("python3", Path.of("../docs/examples/python_agent.py").toString(),
                    Integer.toString(server.port()), "pyrobot", "py-token").redirectErrorStream(true).start();
            List<String> output = new CopyOnWriteArrayList<>();
            Thread.ofVirtual().start(() -> new BufferedReader(new InputStreamReader(p.getInputStream(),
                    StandardCharsets.UTF_8)).lines().forEach(output::add));
            Eventually.await("the Python agent registered", java.time.Duration.ofSeconds(20),
                    () -> output.contains("registered") || !p.isAlive());
            assertThat(output).as("python output").contains("registered");
            // Its battery reading, sent with a time to live of a minute, is there until it leaves.
            Eventually.await("the Python agent's signal is in", () -> kb.contains("signal_pyrobot_battery"));
            long time = ((org.kicnp.core.Value.Int) kb.value("signal_pyrobot_battery", "time").orElseThrow()).value();
            assertThat(kb.value("signal_pyrobot_battery", "expires")).contains(org.kicnp.core.Value.of(time + 60_000));

            server.actionSink().send(new Command("py-1", "pyrobot", "wave", Map.of()));
            assertThat(p.waitFor(20, TimeUnit.SECONDS)).as("python agent finished").isTrue();
            assertThat(p.exitValue()).as("exit status; output: %s", output).isZero();
            assertThat(heard).containsExactly("started py-1", "ended py-1: did wave in Python");
            assertThat(output.getLast()).startsWith("done; 1 signal frame(s);"); // its query saw its own signal
            if (succeeds("python3", "-c", "import jsonschema")) {
                // then all 11 messages of the session (and any heartbeat) were checked against the published schemas
                assertThat(output.getLast())
                        .matches("done; 1 signal frame\\(s\\); (1[1-9]|[2-9][0-9]) message\\(s\\) checked.*");
            }
            Eventually.await("its signal is retracted with its presence", () -> !kb.contains("signal_pyrobot_battery")
                    && !kb.contains("agent_pyrobot"));
        }
    }

    @Test
    void pythonRobotAgent_overTls_trustingExactlyTheServersCertificate(@TempDir Path dir) throws Exception {
        assumeTrue(python(), "python3 is not installed");
        Path store = dir.resolve("gateway.p12");
        Path pem = dir.resolve("gateway.pem");
        keytool("-genkeypair", "-alias", "kicnp", "-keyalg", "EC", "-groupname", "secp256r1", "-dname",
                "CN=localhost", "-ext", "san=ip:127.0.0.1", "-validity", "2", "-storetype", "PKCS12", "-keystore",
                store.toString(), "-storepass", "changeit", "-keypass", "changeit");
        keytool("-exportcert", "-rfc", "-alias", "kicnp", "-keystore", store.toString(), "-storepass", "changeit",
                "-file", pem.toString());
        KeyStore ks = KeyStore.getInstance(store.toFile(), "changeit".toCharArray());
        KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
        kmf.init(ks, "changeit".toCharArray());
        KnowledgeBase kb = KnowledgeBase.create();
        List<String> heard = new CopyOnWriteArrayList<>();
        AgentDirectory agents = AgentDirectory.empty().with("pyrobot", "py-token", AgentKind.ROBOT);
        try (GatewayServer server = GatewayServer.start(GatewayConfig.defaults().withPort(0)
                .withTls(SslContextBuilder.forServer(kmf).build()), agents, kb,
                new GatewayEndToEndTest.Recorder(heard))) {
            Process p = new ProcessBuilder("python3", Path.of("../docs/examples/python_agent.py").toString(),
                    Integer.toString(server.port()), "pyrobot", "py-token", "127.0.0.1", pem.toString())
                    .redirectErrorStream(true).start();
            List<String> output = new CopyOnWriteArrayList<>();
            Thread.ofVirtual().start(() -> new BufferedReader(new InputStreamReader(p.getInputStream(),
                    StandardCharsets.UTF_8)).lines().forEach(output::add));
            Eventually.await("the Python agent registered over TLS", java.time.Duration.ofSeconds(20),
                    () -> output.contains("registered") || !p.isAlive());
            assertThat(output).as("python output").contains("registered");

            server.actionSink().send(new Command("py-tls", "pyrobot", "wave", Map.of()));
            assertThat(p.waitFor(20, TimeUnit.SECONDS)).as("python agent finished").isTrue();
            assertThat(p.exitValue()).as("exit status; output: %s", output).isZero();
            assertThat(heard).containsExactly("started py-tls", "ended py-tls: did wave in Python");

            // Trusting another certificate, the same agent does not get past the handshake.
            Path other = dir.resolve("other.p12");
            Path otherPem = dir.resolve("other.pem");
            keytool("-genkeypair", "-alias", "other", "-keyalg", "EC", "-groupname", "secp256r1", "-dname",
                    "CN=other", "-ext", "san=ip:127.0.0.1", "-validity", "2", "-storetype", "PKCS12", "-keystore",
                    other.toString(), "-storepass", "changeit", "-keypass", "changeit");
            keytool("-exportcert", "-rfc", "-alias", "other", "-keystore", other.toString(), "-storepass",
                    "changeit", "-file", otherPem.toString());
            Process refused = new ProcessBuilder("python3", Path.of("../docs/examples/python_agent.py").toString(),
                    Integer.toString(server.port()), "pyrobot", "py-token", "127.0.0.1", otherPem.toString())
                    .redirectErrorStream(true).start();
            String said = new String(refused.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(refused.waitFor(20, TimeUnit.SECONDS)).isTrue();
            assertThat(refused.exitValue()).isNotZero();
            assertThat(said).contains("CERTIFICATE_VERIFY_FAILED").doesNotContain("registered");
        }
    }

    private static void keytool(String... args) throws Exception {
        List<String> cmd = new java.util.ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "keytool").toString());
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).as("keytool finished").isTrue();
        assertThat(p.exitValue()).as("keytool: %s", output).isZero();
    }

    private static boolean python() {
        return succeeds("python3", "--version");
    }

    private static boolean succeeds(String... command) {
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            return p.waitFor(20, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (Exception e) {
            return false;
        }
    }
}
