package org.kicnp.robots;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.gateway.AgentDirectory;
import org.kicnp.gateway.FeedbackListener;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.GatewayServer;
import org.kicnp.protocol.AgentKind;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.kicnp.robots.SimWorldTest.waitUntil;

/**
 * The paper's Table 5 played through a real gateway by the four robot agents and the simulator: a stranger is
 * seen as unknown, the platform learns the face under the name heard, the robots greet, shake hands, bring tea and
 * lie down, and on the next visit Robovie recognises the user by name.
 */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class Table5ScenarioTest {
    private static final Duration WAIT = Duration.ofSeconds(30);

    private final KnowledgeBase kb = FaceMemoryTest.users();
    private final List<AgentBase> agents = new ArrayList<>();
    private SimWorld world;
    private GatewayServer server;
    private UserAgent director;

    @BeforeEach
    void start() {
        AgentDirectory directory = AgentDirectory.empty().with("director", "d-token", AgentKind.USER);
        for (String robot : List.of("robovie", "pino", "scout", "aibo")) {
            directory = directory.with(robot, robot + "-token", AgentKind.ROBOT);
        }
        world = SimWorld.start(SimOptions.defaults().withSeed(2004).withTimeScale(20));
        server = GatewayServer.start(GatewayConfig.defaults().withPort(0), directory, kb, FeedbackListener.NONE);
        connect(new RobovieAgent(options("robovie"), world));
        connect(new PinoAgent(options("pino"), world));
        connect(new ScoutAgent(options("scout"), world));
        connect(new AiboAgent(options("aibo"), world));
        director = connect(new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "director", AgentKind.USER, "d-token")));
    }

    private AgentOptions options(String robot) {
        return AgentOptions.of("127.0.0.1", server.port(), robot, AgentKind.ROBOT, robot + "-token");
    }

    private <A extends AgentBase> A connect(A agent) {
        agents.add(agent);
        agent.startAndAwait(WAIT);
        return agent;
    }

    @AfterEach
    void stop() {
        agents.reversed().forEach(AgentBase::close);
        server.close();
        world.close();
    }

    private String ok(String robot, String action, Map<String, String> args) {
        return director.command(robot, action, args).result(WAIT);
    }

    private Optional<Value> signal(String robot, String sensor, String slot) {
        String frame = "signal_" + robot + "_" + sensor;
        return kb.contains(frame) ? kb.value(frame, slot) : Optional.empty();
    }

    @Test
    void table5_fromAStrangerToAKnownUserWithTea() throws Exception {
        world.call(new SimRequest.SpawnUser("userA", 4.0, 0.6, 90, Optional.empty()));
        world.call(new SimRequest.MoveUser("userA", 4.0, 2.0, Optional.empty(), Optional.of(0.8)));
        waitUntil(() -> signal("robovie", "face_seen", "value").isPresent());
        assertThat(signal("robovie", "face_seen", "value")).contains(Value.of(RobotDriver.UNKNOWN));

        ok("robovie", "RobovieSay", Map.of("text", "How are you! I have never seen you before. What is your name?"));
        Value.Lst values = (Value.Lst) signal("robovie", "face_seen", "values").orElseThrow();
        FaceMemory.remember(kb, "XXX", faceOf(values.items().get(1))); // GotNewName: "My name is XXX."
        ok("robovie", "RobovieSay", Map.of("text", "Hi, XXX. Nice to meet you. Welcome you to visit my room."));
        ok("robovie", "RobovieApproachUser", Map.of("user", "userA", "distance_m", "0.3"));
        ok("robovie", "RobovieShakeHands", Map.of("user", "userA"));
        ok("robovie", "RobovieSay", Map.of("text", "This is my friend, PINO."));
        ok("pino", "PinoApproachUser", Map.of("user", "userA", "distance_m", "0.4"));
        ok("pino", "PinoShakeHands", Map.of("user", "userA"));
        ok("robovie", "RobovieSay", Map.of("text", "What do you want to drink?"));
        ok("scout", "ScoutGoTo", Map.of("x", "6.85", "y", "3.7"));
        assertThat(ok("scout", "ScoutPickUp", Map.of("cup", "tea"))).contains("tea-1");
        ok("scout", "ScoutApproachUser", Map.of("user", "userA", "distance_m", "0.3"));
        ok("scout", "ScoutHandOver", Map.of("user", "userA"));
        ok("robovie", "RobovieSay", Map.of("text", "This is a robot dog AIBO. Please enjoy yourself with it."));
        ok("aibo", "AiboApproachUser", Map.of("user", "userA", "distance_m", "0.3"));
        ok("aibo", "AiboLieDown", Map.of());

        var state = world.query();
        assertThat(state.at("/users/userA/holding/0").asText()).isEqualTo("tea-1");
        assertThat(state.at("/robots/aibo/posture").asText()).isEqualTo("lie_down");
        assertThat(kb.value("feedback_aibo_AiboLieDown", "status")).contains(Value.of("ended"));

        world.call(new SimRequest.RemoveUser("userA"));
        ok("robovie", "RobovieTurnTo", Map.of("heading_deg", "-90"));
        world.call(new SimRequest.SpawnUser("userA", 4.0, 1.0, 90, Optional.empty()));
        waitUntil(() -> signal("robovie", "face_seen", "value").equals(Optional.of(Value.of("XXX"))));
    }

    private static FaceVector faceOf(Value list) {
        return FaceVector.of(((Value.Lst) list).items().stream().map(v -> ((Value.Real) v).value()).toList());
    }
}
