package org.kicnp.robots;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kicnp.agent.ActionFailedException;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.CommandTicket;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.gateway.AgentDirectory;
import org.kicnp.gateway.FeedbackListener;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.GatewayServer;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.FeedbackStage;
import org.kicnp.protocol.Message.Command;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.kicnp.robots.SimWorldTest.kill9;
import static org.kicnp.robots.SimWorldTest.waitUntil;

/** Platform → gateway (real, on loopback) → robot agent → simulator (real subprocess) → feedback and signals. */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class RobotAgentEndToEndTest {
    private static final Duration WAIT = Duration.ofSeconds(20);
    private static final AgentDirectory AGENTS = AgentDirectory.empty()
            .with("robovie", "robovie-token", AgentKind.ROBOT)
            .with("pino", "pino-token", AgentKind.ROBOT)
            .with("scout", "scout-token", AgentKind.ROBOT)
            .with("aibo", "aibo-token", AgentKind.ROBOT)
            .with("alice", "alice-token", AgentKind.USER);

    private final KnowledgeBase kb = FaceMemoryTest.users();
    private final Map<String, String> outcomes = new ConcurrentHashMap<>();
    private final List<AutoCloseable> open = new ArrayList<>();
    private SimWorld world;
    private GatewayServer server;

    @BeforeEach
    void start() {
        world = SimWorld.start(SimOptions.defaults().withTimeScale(10));
        server = GatewayServer.start(GatewayConfig.defaults().withPort(0), AGENTS, kb, new FeedbackListener() {
            @Override public void ended(Command command, String result) {
                outcomes.put(command.id(), "ended " + result);
            }

            @Override public void failed(Command command, String reason) {
                outcomes.put(command.id(), "failed " + reason);
            }
        });
    }

    @AfterEach
    void stop() throws Exception {
        for (AutoCloseable c : open.reversed()) {
            c.close();
        }
        server.close();
        world.close();
    }

    private AgentOptions options(String name, AgentKind kind) {
        return AgentOptions.of("127.0.0.1", server.port(), name, kind, name + "-token");
    }

    private <A extends org.kicnp.agent.AgentBase> A connect(A agent) {
        open.add(agent);
        agent.startAndAwait(WAIT);
        return agent;
    }

    @Test
    void platformCommandToScout_travelsThroughTheGatewayAndEndsWithFeedback() {
        connect(new ScoutAgent(options("scout", AgentKind.ROBOT), world));
        assertThat(server.registeredAgents()).contains("scout");
        assertThat(kb.require("ScoutGoTo").parent()).contains(ActionSpec.ROOT);

        server.actionSink().send(new Command("p-1", "scout", "ScoutGoTo", Map.of("x", "6.2", "y", "3.5")));

        eventually("the go_to ends", () -> outcomes.containsKey("p-1"));
        assertThat(outcomes.get("p-1")).startsWith("ended {\"x\":6.2,");
        assertThat(valueOf("feedback_scout_ScoutGoTo", "status")).contains(Value.of("ended"));
        assertThat(valueOf("signal_scout_arrival", "value")).contains(Value.of("point"));
    }

    @Test
    void userCommands_toEachRobot_comeBackWithTheirResults() {
        connect(new RobovieAgent(options("robovie", AgentKind.ROBOT), world));
        connect(new PinoAgent(options("pino", AgentKind.ROBOT), world));
        connect(new AiboAgent(options("aibo", AgentKind.ROBOT), world));
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));
        world.call(new SimRequest.SpawnUser("alice", 2.0, 2.6, 90, Optional.empty()));

        CommandTicket say = alice.command("robovie", "RobovieSay", Map.of("text", "This is my friend, PINO."));
        CommandTicket walk = alice.command("pino", "PinoApproachUser", Map.of("user", "alice"));
        CommandTicket lie = alice.command("aibo", "AiboLieDown", Map.of());

        assertThat(say.result(WAIT)).contains("\"text\":\"This is my friend, PINO.\"");
        assertThat(say.feedback().getFirst().stage()).isEqualTo(FeedbackStage.STARTED);
        assertThat(walk.result(WAIT)).contains("\"user\":\"alice\"");
        assertThat(alice.command("pino", "PinoShakeHands", Map.of("user", "alice")).result(WAIT)).contains("\"duration_s\":2.0");
        assertThat(lie.result(WAIT)).isEqualTo("{\"posture\":\"lie_down\",\"duration_s\":1.5}");
        assertThat(valueOf("signal_robovie_utterance", "value")).contains(Value.of("This is my friend, PINO."));
    }

    @Test
    void robovie_recognisesAKnownUserFromTheKnowledgeBase_andOneLearnedWhileConnected() throws Exception {
        var aliceAck = world.call(new SimRequest.SpawnUser("alice", 1.0, 5.5, 90, Optional.empty())).orElseThrow();
        var bobAck = world.call(new SimRequest.SpawnUser("bob", 2.0, 5.5, 90, Optional.empty())).orElseThrow();
        FaceMemory.remember(kb, "alice", face(aliceAck));
        RobovieAgent robovie = connect(new RobovieAgent(options("robovie", AgentKind.ROBOT), world));
        waitUntil(() -> robovie.faces().names().contains("alice"));

        world.call(new SimRequest.MoveUser("alice", 4.0, 1.4, Optional.of(90.0), Optional.empty()));
        eventually("Robovie reports alice", () -> valueOf("signal_robovie_face_seen", "value")
                .equals(Optional.of(Value.of("alice"))));
        world.call(new SimRequest.RemoveUser("alice"));
        FaceMemory.remember(kb, "bob", face(bobAck));
        waitUntil(() -> robovie.faces().names().contains("bob"));
        world.call(new SimRequest.MoveUser("bob", 4.0, 1.4, Optional.of(90.0), Optional.empty()));

        eventually("Robovie reports bob", () -> valueOf("signal_robovie_face_seen", "value")
                .equals(Optional.of(Value.of("bob"))));
    }

    @Test
    void aUserCancelsScoutsGoTo_theSimulatorHaltsScout_andTheCommandFailsAsCancelled() throws Exception {
        UserAgent alice = scoutAndAlice();
        CommandTicket go = scoutUnderWay(alice);

        alice.cancel("scout", go.command().id(), "the user changed her mind");

        assertThatThrownBy(() -> go.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessage("cancelled: the user changed her mind (asked by 'alice')");
        // Halted: Scout takes new commands at once (a robot still driving would refuse a second go_to as busy).
        assertThat(alice.command("scout", "ScoutGoTo", Map.of("x", "6.2", "y", "3.5")).result(WAIT))
                .contains("\"distance_error_m\"");
    }

    @Test
    void aCancelAndANewCommandAtOnce_theNewOneWaitsForScoutToHalt_thenRuns() throws Exception {
        UserAgent alice = scoutAndAlice();
        CommandTicket go = scoutUnderWay(alice);

        // A preemption, as the platform sends one: the cancel, then at once the new goal (no wait for the cancel's end).
        alice.cancel("scout", go.command().id(), "go elsewhere");
        CommandTicket elsewhere = alice.command("scout", "ScoutGoTo", Map.of("x", "6.2", "y", "3.5"));

        assertThat(elsewhere.result(WAIT)).contains("\"distance_error_m\"");
        assertThatThrownBy(() -> go.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessage("cancelled: go elsewhere (asked by 'alice')");
    }

    @Test
    void aCommandForAPartThatIsBusy_failsNamingTheRunningCommandByItsPlatformId() throws Exception {
        UserAgent alice = scoutAndAlice();
        CommandTicket go = scoutUnderWay(alice);

        CommandTicket turn = alice.command("scout", "ScoutTurnTo", Map.of("heading_deg", "0")); // no cancel first

        assertThatThrownBy(() -> turn.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessage("refused: scout base is busy with go_to '" + go.command().id() + "'");
    }

    /** Scout's agent and the user agent alice, connected, the simulator in real time. */
    private UserAgent scoutAndAlice() throws Exception {
        connect(new ScoutAgent(options("scout", AgentKind.ROBOT), world));
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));
        world.call(new SimRequest.SetTimeScale(1));
        return alice;
    }

    /** Alice sends Scout to (1, 1), a trip of several seconds; answers once Scout reports progress. */
    private static CommandTicket scoutUnderWay(UserAgent alice) throws Exception {
        CommandTicket go = alice.command("scout", "ScoutGoTo", Map.of("x", "1", "y", "1"));
        waitUntil(() -> go.feedback().stream().anyMatch(f -> f.stage() == FeedbackStage.PROGRESS));
        return go;
    }

    @Test
    void simulatorKilledMidAction_theCommandFailsWithTheReasonThroughTheGateway() throws Exception {
        connect(new ScoutAgent(options("scout", AgentKind.ROBOT), world));
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));
        world.call(new SimRequest.SetTimeScale(1));
        CommandTicket go = alice.command("scout", "ScoutGoTo", Map.of("x", "1", "y", "1"));
        waitUntil(() -> !go.feedback().isEmpty());

        kill9(world.pid());

        assertThatThrownBy(() -> go.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessageContaining("simulator exited with code 137");
        eventually("the agent reports the simulator's death", () -> valueOf("signal_scout_simulator", "value")
                .equals(Optional.of(Value.of("exited"))));
        assertThatThrownBy(() -> alice.command("scout", "ScoutTurnTo", Map.of("heading_deg", "0")).result(WAIT))
                .isInstanceOf(ActionFailedException.class)
                .hasMessageContaining("simulator exited with code 137");
    }

    private Optional<Value> valueOf(String frame, String slot) {
        return kb.contains(frame) ? kb.value(frame, slot) : Optional.empty();
    }

    private static FaceVector face(com.fasterxml.jackson.databind.JsonNode spawnAck) {
        List<Double> v = new ArrayList<>();
        spawnAck.get("face").forEach(n -> v.add(n.asDouble()));
        return FaceVector.of(v);
    }

    private static void eventually(String what, java.util.function.BooleanSupplier condition) {
        long deadline = System.nanoTime() + WAIT.toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("Timed out waiting until " + what + ".");
            }
            try {
                Thread.sleep(10);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new AssertionError("Interrupted waiting until " + what + ".");
            }
        }
    }
}
