package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import io.netty.handler.ssl.SslContextBuilder;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyStore;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.KeyManagerFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.FrameText;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.Command;
import org.kicnp.protocol.ValueJson;

/**
 * The Python agent SDK (kicnp-agent-py) against a real gateway. Its unittest suite runs as a subprocess and, through
 * this test's {@link Harness} on its stdin and stdout, asks the gateway's side to act (send a command through the
 * {@link ActionSink}, cancel it, restart the server) and to tell what it saw (the feedback the platform heard, the
 * knowledge base); the Python tests assert on both sides of each exchange, and this test then checks the gateway's
 * side of the whole run.
 */
class PythonSdkTest {
    private static final Path SDK = Path.of("../kicnp-agent-py");
    private static final AgentDirectory AGENTS = AgentDirectory.empty()
            .with("pyrobot", "robot-token", AgentKind.ROBOT)
            .with("pyrobot2", "robot2-token", AgentKind.ROBOT)
            .with("pyuser", "user-token", AgentKind.USER)
            .with("scout", "scout-token", AgentKind.ROBOT)
            .with("pypeer", "peer-token", AgentKind.PEER);
    /** The knowledge the Python tests read and change: cups, and the runtime classes the gateway fills. */
    private static final String KNOWLEDGE = """
            <KNOWLEDGEBASE>
              <FRAME><NAME>Cup</NAME><SLOTLIST>
                <SLOT><NAME>ml</NAME><TYPE>TYPE_INT</TYPE></SLOT>
                <SLOT><NAME>colour</NAME><TYPE>TYPE_STR</TYPE></SLOT>
                <SLOT><NAME>owner</NAME><TYPE>TYPE_STR</TYPE></SLOT>
              </SLOTLIST></FRAME>
              <FRAME><NAME>cup1</NAME><ISA>Cup</ISA><ISINSTANCE>TRUE</ISINSTANCE><SLOTLIST>
                <SLOT><NAME>ml</NAME><VALUE>250</VALUE></SLOT>
                <SLOT><NAME>colour</NAME><VALUE>blue</VALUE></SLOT>
              </SLOTLIST></FRAME>
              <FRAME><NAME>SensorSignal</NAME><SLOTLIST>
                <SLOT><NAME>source</NAME><TYPE>TYPE_STR</TYPE></SLOT>
                <SLOT><NAME>sensor</NAME><TYPE>TYPE_STR</TYPE></SLOT>
                <SLOT><NAME>time</NAME><TYPE>TYPE_INT</TYPE></SLOT>
                <SLOT><NAME>values</NAME><TYPE>TYPE_LIST</TYPE></SLOT>
              </SLOTLIST></FRAME>
            </KNOWLEDGEBASE>
            """;

    @Test
    void pythonSdk_unittestSuite_passesAgainstARealGateway() throws Exception {
        assumeTrue(succeeds("python3", "--version"), "python3 is not installed");
        // A short heartbeat timeout, so that the suite can show an idle agent kept alive and a silent one dropped.
        try (Harness gateway = new Harness(GatewayConfig.defaults().withPort(0).withHeartbeatTimeout(Duration.ofSeconds(3)))) {
            Run run = gateway.run(Map.of(), "-m", "unittest", "discover", "-s", "tests", "-v");
            assertThat(run.exit()).as("python3 -m unittest exit status; its output:%n%s", run.output()).isZero();
            // The gateway tests ran rather than skipped (only the TLS module waits for its own run, below).
            assertThat(run.output()).contains(
                    "test_command_fromThePlatform_runsItsHandlerOffTheReaderThread_andTheFeedbackReachesThePlatform"
                            + " (test_commands.RobotCommandsTest", "OK (skipped=2)")
                    .doesNotContain("FAILED");
            // What the gateway saw of the run: every message well formed, the commands' feedback, and nobody left.
            assertThat(gateway.server.metrics().protocolErrors()).as("protocol errors").isZero();
            assertThat(gateway.heard).contains("started py-wave", "progress py-wave 0.5 halfway",
                    "ended py-wave: waved 3 times", "failed py-raise: Agent 'pyrobot' failed on 'grab': ValueError: no arm",
                    "failed py-cancel: cancelled: stop now", "ended py-after-restart: waved 1 times",
                    "ended py-tea: brought a cup of milk", "failed py-brakes: cancel failed: RuntimeError: brakes (agent "
                    + "'pyrobot', asked to stop: stop now); the robot may not have stopped");
            Eventually.await("every Python agent is gone", () -> gateway.server.registeredAgents().isEmpty());
            assertThat(gateway.kb.instancesOf("SensorSignal")).isEmpty();
            assertThat(gateway.kb.contains("mug1")).as("what the Python peer pushed").isTrue();
        }
    }

    @Test
    void pythonSdk_overTls_trustsExactlyTheServersCertificate(@TempDir Path dir) throws Exception {
        assumeTrue(succeeds("python3", "--version"), "python3 is not installed");
        Path store = dir.resolve("gateway.p12");
        Path pem = dir.resolve("gateway.pem");
        Path otherPem = dir.resolve("other.pem");
        certificate("kicnp", "CN=localhost", store, pem);
        certificate("other", "CN=other", dir.resolve("other.p12"), otherPem);
        KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
        kmf.init(KeyStore.getInstance(store.toFile(), "changeit".toCharArray()), "changeit".toCharArray());
        try (Harness gateway = new Harness(GatewayConfig.defaults().withPort(0)
                .withTls(SslContextBuilder.forServer(kmf).build()))) {
            Run run = gateway.run(Map.of("KICNP_TLS_TRUST", pem.toString(), "KICNP_TLS_OTHER", otherPem.toString()),
                    "-m", "unittest", "discover", "-s", "tests", "-p", "test_tls.py", "-v");
            assertThat(run.exit()).as("python3 -m unittest exit status; its output:%n%s", run.output()).isZero();
            assertThat(run.output()).contains("Ran 2 tests", "OK").doesNotContain("skipped");
            assertThat(gateway.heard).containsExactly("started py-tls", "ended py-tls: waved 1 times");
            assertThat(gateway.server.metrics().protocolErrors()).isZero();
        }
    }

    /**
     * {@code pip install ./kicnp-agent-py} into a fresh virtual environment, as README tells a robot developer, and
     * README's robot run by that environment's Python from the installed package (not the source tree): it registers,
     * carries out a command and stops cleanly (test_readme.py, told by {@code KICNP_SDK_INSTALLED} to check where
     * {@code kicnp_agent} comes from). pip fetches the build back end (setuptools, wheel) from the package index.
     */
    @Test
    void pythonSdk_installedWithPip_runsReadmesRobot(@TempDir Path dir) throws Exception {
        assumeTrue(succeeds("python3", "--version"), "python3 is not installed");
        Path venv = dir.resolve("venv");
        String python = venv.resolve("bin/python").toString();
        // pip builds in the directory it is given (build/, *.egg-info): a copy, so the source tree stays as it is.
        Path copy = dir.resolve("kicnp-agent-py");
        for (String part : List.of("pyproject.toml", "README.md", "kicnp_agent")) {
            copyTree(SDK.resolve(part), copy.resolve(part));
        }
        assertThat(runs(600, "python3", "-m", "venv", venv.toString())).isEmpty();
        assertThat(runs(600, python, "-m", "pip", "install", "--disable-pip-version-check", "-q", copy.toString()))
                .isEmpty();
        try (Harness gateway = new Harness(GatewayConfig.defaults().withPort(0))) {
            Run run = gateway.run(python, Map.of("KICNP_SDK_INSTALLED", "1"),
                    "-m", "unittest", "discover", "-s", "tests", "-p", "test_readme.py", "-v");
            assertThat(run.exit()).as("unittest exit status; its output:%n%s", run.output()).isZero();
            assertThat(run.output()).contains("Ran 2 tests", "OK").doesNotContain("skipped");
            assertThat(gateway.heard).contains("started py-tea", "ended py-tea: brought a cup of milk");
        }
    }

    private static void copyTree(Path from, Path to) throws IOException {
        try (var paths = Files.walk(from)) {
            for (Path p : paths.filter(q -> !q.toString().contains("__pycache__")).toList()) {
                Path target = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(target);
                } else {
                    Files.createDirectories(target.getParent());
                    Files.copy(p, target);
                }
            }
        }
    }

    /** Runs a command to its end; answers its output when it failed, else an empty string. */
    private static String runs(int seconds, String... command) throws Exception {
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        CompletableFuture<String> output = CompletableFuture.supplyAsync(() -> {
            try {
                return new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            } catch (IOException e) {
                return e.toString();
            }
        });
        if (!p.waitFor(seconds, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            return String.join(" ", command) + ": still running after " + seconds + " s";
        }
        return p.exitValue() == 0 ? "" : String.join(" ", command) + " exited " + p.exitValue() + ":\n"
                + output.get(10, TimeUnit.SECONDS);
    }

    /** What the Python suite printed, and how it exited. */
    record Run(int exit, String output) {
    }

    /**
     * A gateway for the Python suite, and the Python side's way to act on it: each line the suite writes to stdout
     * that starts with {@code KICNP-HARNESS } is a JSON request ({@code op} and its arguments) answered with one JSON
     * line on its stdin ({@code ok}, and what was asked for, or {@code error}).
     */
    static final class Harness implements AutoCloseable {
        private final ObjectMapper json = new ObjectMapper();
        private final GatewayConfig config;
        final List<String> heard = new CopyOnWriteArrayList<>();
        volatile KnowledgeBase kb;
        volatile GatewayServer server;

        Harness(GatewayConfig config) {
            this.config = config;
            this.kb = knowledge();
            this.server = start(config, kb);
        }

        private GatewayServer start(GatewayConfig c, KnowledgeBase k) {
            return GatewayServer.start(c, AGENTS, k, new Recorder(heard), Retraction.removeFrom(k), new Explainer());
        }

        Run run(Map<String, String> env, String... args) throws Exception {
            return run("python3", env, args);
        }

        /** As {@link #run(Map, String...)}, with the given Python interpreter. */
        Run run(String python, Map<String, String> env, String... args) throws Exception {
            List<String> command = new ArrayList<>(List.of(python));
            command.addAll(List.of(args));
            ProcessBuilder pb = new ProcessBuilder(command).directory(SDK.toFile());
            pb.environment().put("KICNP_PORT", Integer.toString(server.port()));
            pb.environment().put("KICNP_AGENTS", "pyrobot:robot:robot-token,pyrobot2:robot:robot2-token,"
                    + "pyuser:user:user-token,scout:robot:scout-token,pypeer:peer:peer-token");
            pb.environment().put("PYTHONDONTWRITEBYTECODE", "1");
            pb.environment().putAll(env);
            Process p = pb.start();
            List<String> output = new CopyOnWriteArrayList<>();
            Thread errors = Thread.ofVirtual().start(() -> new BufferedReader(new InputStreamReader(p.getErrorStream(),
                    StandardCharsets.UTF_8)).lines().forEach(output::add));
            Thread requests = Thread.ofVirtual().start(() -> serve(p, output));
            boolean finished = p.waitFor(300, TimeUnit.SECONDS);
            if (!finished) {
                p.destroyForcibly();
            }
            errors.join(5_000);
            requests.join(5_000);
            assertThat(finished).as("the Python suite finished within 300 s; its output:%n%s", String.join("\n", output))
                    .isTrue();
            return new Run(p.exitValue(), String.join("\n", output));
        }

        private void serve(Process p, List<String> output) {
            try (BufferedReader in = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
                 Writer out = new OutputStreamWriter(p.getOutputStream(), StandardCharsets.UTF_8)) {
                String line;
                while ((line = in.readLine()) != null) {
                    if (!line.startsWith("KICNP-HARNESS ")) {
                        output.add(line);
                        continue;
                    }
                    ObjectNode reply = json.createObjectNode();
                    try {
                        answer(json.readTree(line.substring("KICNP-HARNESS ".length())), reply);
                        reply.put("ok", true);
                    } catch (RuntimeException e) {
                        reply.put("ok", false).put("error", e.toString());
                    }
                    out.write(json.writeValueAsString(reply) + "\n");
                    out.flush();
                }
            } catch (IOException e) {
                output.add("harness: " + e);
            }
        }

        private void answer(JsonNode request, ObjectNode reply) {
            switch (request.get("op").asText()) {
                case "command" -> {
                    Map<String, String> args = new LinkedHashMap<>();
                    request.get("args").properties().forEach(e -> args.put(e.getKey(), e.getValue().asText()));
                    server.actionSink().send(new Command(request.get("id").asText(), request.get("robot").asText(),
                            request.get("action").asText(), args));
                }
                case "cancel" -> reply.put("cancelled", server.actionSink().cancel(request.get("robot").asText(),
                        request.get("command").asText(), request.get("reason").asText()));
                case "heard" -> heard.forEach(reply.putArray("heard")::add);
                case "agents" -> server.registeredAgents().forEach(reply.putArray("agents")::add);
                case "contains" -> reply.put("contains", kb.contains(request.get("frame").asText()));
                case "value" -> kb.value(request.get("frame").asText(), request.get("slot").asText())
                        .ifPresent(v -> reply.set("value", ValueJson.toJson(v)));
                case "put" -> FrameText.parse(request.get("xml").asText(), "the Python suite", kb).forEach(kb::put);
                case "restart" -> {
                    int port = server.port();
                    server.close();
                    kb = knowledge();
                    server = start(config.withPort(port), kb);
                }
                default -> throw new IllegalArgumentException("Unknown harness op in " + request + ".");
            }
        }

        private static KnowledgeBase knowledge() {
            KnowledgeBase k = KnowledgeBase.create();
            FrameText.parse(KNOWLEDGE, "PythonSdkTest", k).forEach(k::put);
            return k;
        }

        @Override public void close() {
            server.close();
        }
    }

    /** Records what the platform's feedback listener hears, progress included, as sentences. */
    record Recorder(List<String> heard) implements FeedbackListener {
        @Override public void started(Command c) {
            heard.add("started " + c.id());
        }

        @Override public void progress(Command c, double fraction, String note) {
            heard.add("progress " + c.id() + " " + fraction + " " + note);
        }

        @Override public void ended(Command c, String result) {
            heard.add("ended " + c.id() + ": " + result);
        }

        @Override public void failed(Command c, String reason) {
            heard.add("failed " + c.id() + ": " + reason);
        }
    }

    /**
     * Reasoning with fixed answers about {@code cup1}, so that the Python suite can check how it reads each answer
     * of prove, why and why_not as the gateway writes them; anything else is refused, as a server without an engine is.
     */
    static final class Explainer implements Reasoning {
        @Override public CompletableFuture<List<Message.ProofNode>> prove(String ofClass, Map<String, String> bindings) {
            if (!ofClass.equals("Cup")) {
                return CompletableFuture.failedFuture(new IllegalStateException("Only Cup can be proved here."));
            }
            Message.ProofNode user = new Message.ProofNode("User", Optional.of("ken"), Map.of(), List.of());
            return CompletableFuture.completedFuture(List.of(new Message.ProofNode("Cup", Optional.empty(),
                    Map.of("owner", user), List.of("js: s.ml > 0"))));
        }

        @Override public CompletableFuture<Message.Reason> why(String instance) {
            Message.Reason stimulus = new Message.Reason("signal_pyrobot_sonar", "SensorSignal", false, Map.of(),
                    List.of(), List.of());
            return CompletableFuture.completedFuture(new Message.Reason(instance, "Cup", true,
                    Map.of("source", "signal_pyrobot_sonar"), List.of("value: > = 0.5"), List.of(stimulus)));
        }

        @Override public CompletableFuture<Message.NotFired> whyNot(String id, String frame,
                                                                    Map<String, String> bindings) {
            return CompletableFuture.completedFuture(new Message.NotFired(id, frame, "No User is known yet.",
                    List.of(new Message.SlotCandidates("mUser", "KnownUser", "COND_ANY", List.of(), List.of(), 0, 0)),
                    List.of(new Message.BindingOutcome(Map.of("mUser", "ken"), "waiting", "ken has no name yet")),
                    false));
        }
    }

    private static void certificate(String alias, String dname, Path store, Path pem) throws Exception {
        keytool("-genkeypair", "-alias", alias, "-keyalg", "EC", "-groupname", "secp256r1", "-dname", dname, "-ext",
                "san=ip:127.0.0.1", "-validity", "2", "-storetype", "PKCS12", "-keystore", store.toString(),
                "-storepass", "changeit", "-keypass", "changeit");
        keytool("-exportcert", "-rfc", "-alias", alias, "-keystore", store.toString(), "-storepass", "changeit",
                "-file", pem.toString());
    }

    private static void keytool(String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "keytool").toString()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).as("keytool finished").isTrue();
        assertThat(p.exitValue()).as("keytool: %s", output).isZero();
    }

    private static boolean succeeds(String... command) {
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            return p.waitFor(20, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException | InterruptedException e) {
            return false;
        }
    }
}
