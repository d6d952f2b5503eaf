package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.CommandTicket;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.example.TeaRobot;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message.Command;

/** docs/agents.md shows TeaRobot verbatim, and TeaRobot works against a real gateway. */
class AgentsDocTest {
    private static final Path EXAMPLE = Path.of("src/test/java/org/kicnp/example/TeaRobot.java");
    private static final Path DOC = Path.of("../docs/agents.md");

    @Test
    void agentsDoc_containsTheExampleRobotVerbatim() throws Exception {
        String example = Files.readString(EXAMPLE, StandardCharsets.UTF_8);
        assertThat(Files.readString(DOC, StandardCharsets.UTF_8)).contains("```java\n" + example + "```");
    }

    @Test
    void exampleRobot_bringsTea_forAUserAndForThePlatform() {
        KnowledgeBase kb = KnowledgeBase.create();
        List<String> heard = new CopyOnWriteArrayList<>();
        AgentDirectory agents = AgentDirectory.empty().with("scout", "s", AgentKind.ROBOT).with("alice", "a", AgentKind.USER);
        try (GatewayServer server = GatewayServer.start(GatewayConfig.defaults().withPort(0), agents, kb,
                new GatewayEndToEndTest.Recorder(heard));
             TeaRobot scout = new TeaRobot(AgentOptions.of("127.0.0.1", server.port(), "scout", AgentKind.ROBOT, "s"));
             UserAgent alice = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "alice", AgentKind.USER, "a"))) {
            scout.startAndAwait(Duration.ofSeconds(10));
            alice.startAndAwait(Duration.ofSeconds(10));

            CommandTicket tea = alice.command("scout", "bring", Map.of("item", "tea"));
            assertThat(tea.result(Duration.ofSeconds(10))).isEqualTo("brought a cup of tea");
            assertThat(kb.contains("BringTea")).isTrue();
            assertThat(kb.value("signal_scout_sonar", "value")).contains(Value.of(0.5));

            server.actionSink().send(new Command("p1", "scout", "dance", Map.of()));
            Eventually.await("the platform hears the refusal", () -> heard.contains("failed p1: Scout cannot 'dance'."));
        }
    }
}
