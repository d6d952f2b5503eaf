package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
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
