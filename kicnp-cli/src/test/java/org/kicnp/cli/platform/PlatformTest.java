package org.kicnp.cli.platform;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.agent.ActionHandle;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.RequestRefusedException;
import org.kicnp.agent.UserAgent;
import org.kicnp.cli.scenario.ScenarioFiles;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.gateway.Transport;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.Command;

/**
 * The platform in-process on ephemeral ports over a copy of scenarios/table5: an agent asserts a stimulus and the
 * robot agent receives the command the inference engine issued; its feedback reaches the engine.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class PlatformTest {
    @TempDir
    Path tmp;

    /** A stand-in Robovie that records its commands and ends each one. */
    static final class RecordingRobot extends AgentBase {
        final LinkedBlockingQueue<Command> commands = new LinkedBlockingQueue<>();

        RecordingRobot(AgentOptions o) {
            super(o);
        }

        @Override protected void onCommand(Command command, ActionHandle handle) {
            commands.add(command);
            handle.started();
            handle.ended("said it");
        }
    }

    /** Robovie, whose sentences go on until it is told to stop; other commands end at once. */
    static final class TalkingRobovie extends AgentBase {
        final LinkedBlockingQueue<Command> says = new LinkedBlockingQueue<>();
        /** Each cancel heard: "command id: reason". */
        final List<String> cancels = new java.util.concurrent.CopyOnWriteArrayList<>();

        TalkingRobovie(Platform platform) {
            super(AgentOptions.of("127.0.0.1", platform.gatewayPort(), "robovie", AgentKind.ROBOT,
                    platform.token("robovie")));
        }

        @Override protected void onCommand(Command command, ActionHandle handle) {
            handle.started();
            if (command.action().equals("say")) {
                says.add(command);
            } else {
                handle.ended("done");
            }
        }

        @Override protected void onCancel(ActionHandle handle, String reason) {
            cancels.add(handle.command().id() + ": " + reason);
            super.onCancel(handle, reason);
        }

        /** Starts Robovie and {@code user}; User A walks in; answers the sentence Robovie then starts saying. */
        Command firstSentenceTo(UserAgent user) throws InterruptedException {
            startAndAwait(Duration.ofSeconds(10));
            user.startAndAwait(Duration.ofSeconds(10));
            newUserA(user);
            Command say = says.poll(20, TimeUnit.SECONDS);
            assertThat(say).as("Robovie's first sentence").isNotNull();
            return say;
        }
    }

    @Test
    void serve_whenAStimulusIsAsserted_theRobotReceivesTheCommandAndItsFeedbackEndsTheAction() throws Exception {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        try (Platform platform = Platform.start(PlatformConfig.of(kb).withEphemeralPorts())) {
            assertThat(Platform.defaultAgentsFile(kb)).exists();
            assertThat(platform.editorPasswordFile()).hasValueSatisfying(p -> assertThat(p).exists());
            try (RecordingRobot robovie = new RecordingRobot(AgentOptions.of("127.0.0.1", platform.gatewayPort(),
                    "robovie", AgentKind.ROBOT, platform.token("robovie")));
                 UserAgent user = user(platform)) {
                robovie.startAndAwait(Duration.ofSeconds(10));
                user.startAndAwait(Duration.ofSeconds(10));
                newUserA(user);

                Command first = robovie.commands.poll(20, TimeUnit.SECONDS);
                Command second = robovie.commands.poll(20, TimeUnit.SECONDS);
                assertThat(first).isNotNull();
                assertThat(second).isNotNull();
                // FirstMeet: Robovie looks at the face; AskUserName: it asks the name (head and voice, together)
                Command look = first.action().equals("head") ? first : second;
                Command c = look == first ? second : first;
                assertThat(look.action()).isEqualTo("head");
                assertThat(c.robot()).isEqualTo("robovie");
                assertThat(c.action()).isEqualTo("say");
                assertThat(c.args()).containsEntry("text", "How are you! I have never seen you before. What is your name?");
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                while (System.nanoTime() < deadline && !platform.engine().actionStatus(c.id())
                        .map(s -> s.finished()).orElse(false)) {
                    Thread.sleep(20);
                }
                assertThat(platform.engine().actionStatus(c.id())).hasValueSatisfying(
                        s -> assertThat(s.name()).isEqualTo("ENDED"));
            }
            assertThat(platform.events().awaitWritten(Duration.ofSeconds(10))).isTrue();
            List<String> log = Files.readAllLines(platform.events().file());
            assertThat(log).anyMatch(l -> l.contains("\"event\":\"fired\"") && l.contains("AskUserName"));
            assertThat(log).anyMatch(l -> l.contains("\"event\":\"command\"") && l.contains("robovie"));
            assertThat(log).anyMatch(l -> l.contains("\"event\":\"feedback\"") && l.contains("\"stage\":\"ended\""));
        }
    }

    @Test
    void serve_onJavaNio_connectsTheRobotsToo() throws Exception {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        try (Platform platform = Platform.start(PlatformConfig.of(kb).withEphemeralPorts()
                .withGatewayTransport(Transport.NIO))) {
            assertThat(platform.gatewayTransport()).isEqualTo(Transport.NIO);
            try (RecordingRobot robovie = new RecordingRobot(AgentOptions.of("127.0.0.1", platform.gatewayPort(),
                    "robovie", AgentKind.ROBOT, platform.token("robovie")))) {
                robovie.startAndAwait(Duration.ofSeconds(10));
                robovie.sensor("face_seen", Value.of("unknown"),
                        new Value.Lst(List.of(Value.of(0.1), Value.of(0.2), Value.of(0.3))));
                await("FaceDetection fires on the signal sent over NIO",
                        () -> !platform.kb().instancesOf("FaceDetection").isEmpty());
            }
        }
    }

    @Test
    void serve_whenARobotLeaves_itsSignalGoesWithEverythingDerivedFromIt() throws Exception {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        try (Platform platform = Platform.start(PlatformConfig.of(kb).withEphemeralPorts())) {
            RecordingRobot robovie = new RecordingRobot(AgentOptions.of("127.0.0.1", platform.gatewayPort(),
                    "robovie", AgentKind.ROBOT, platform.token("robovie")));
            robovie.startAndAwait(Duration.ofSeconds(10));
            robovie.sensor("face_seen", Value.of("unknown"),
                    new Value.Lst(List.of(Value.of(0.1), Value.of(0.2), Value.of(0.3))));
            await("FaceDetection fires on the signal", () -> !platform.kb().instancesOf("FaceDetection").isEmpty()
                    && !platform.kb().instancesOf("NewUser").isEmpty());

            robovie.close();

            // The gateway hands each frame to the engine thread separately, so they go one after the other.
            await("the signal and what rests on it are retracted, and the presence too", () -> !platform.kb()
                    .contains("signal_robovie_face_seen") && platform.kb().instancesOf("FaceDetection").isEmpty()
                    && platform.kb().instancesOf("NewUser").isEmpty() && !platform.kb().contains("agent_robovie"));
        }
    }

    @Test
    void serve_whenASignalsTimeToLiveIsOver_itGoesWithEverythingDerivedFromIt_andTheRobotStays() throws Exception {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        try (Platform platform = Platform.start(PlatformConfig.of(kb).withEphemeralPorts());
             RecordingRobot robovie = new RecordingRobot(AgentOptions.of("127.0.0.1", platform.gatewayPort(),
                     "robovie", AgentKind.ROBOT, platform.token("robovie")))) {
            List<org.kicnp.inference.TraceEvent> trace = new java.util.concurrent.CopyOnWriteArrayList<>();
            platform.engine().addTraceListener(trace::add);
            robovie.startAndAwait(Duration.ofSeconds(10));
            robovie.sensor("face_seen", Duration.ofMillis(1500), Value.of("unknown"),
                    new Value.Lst(List.of(Value.of(0.1), Value.of(0.2), Value.of(0.3))));
            await("FaceDetection fires on the signal", () -> !platform.kb().instancesOf("FaceDetection").isEmpty()
                    && !platform.kb().instancesOf("NewUser").isEmpty());
            String detection = platform.kb().instancesOf("FaceDetection").getFirst().name();

            await("the reading expired and what rests on it went with it", () -> !platform.kb()
                    .contains("signal_robovie_face_seen") && platform.kb().instancesOf("FaceDetection").isEmpty()
                    && platform.kb().instancesOf("NewUser").isEmpty());
            assertThat(platform.kb().contains("agent_robovie")).isTrue();
            assertThat(robovie.isConnected()).isTrue();
            // The engine traces a retraction once the knowledge base has applied it, so the trace may lag the state
            // awaited above by a moment: wait for it too.
            org.kicnp.inference.TraceEvent why = new org.kicnp.inference.TraceEvent.Retracted(detection,
                    "it rests on 'signal_robovie_face_seen', which was retracted as stale (no newer version came in "
                            + "its time to live)");
            await("the trace says why " + detection + " went", () -> trace.contains(why));
        }
    }

    @Test
    void serve_whenAnAgentDestroysAnInstance_whatWasDerivedFromItGoesToo() throws Exception {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        try (Platform platform = Platform.start(PlatformConfig.of(kb).withEphemeralPorts());
             UserAgent user = user(platform)) {
            user.startAndAwait(Duration.ofSeconds(10));
            newUserA(user);
            await("the engine derives from userA", () -> !platform.kb().referrers("userA").isEmpty());
            List<String> derived = List.copyOf(platform.kb().referrers("userA"));

            // A plain removal is refused while a derived instance refers to userA; the gateway destroys through
            // the engine, which takes the derived instances with it, and answers once that is done.
            user.destroy("userA");

            assertThat(platform.kb().contains("userA")).isFalse();
            assertThat(derived).isNotEmpty().noneMatch(platform.kb()::contains);
        }
    }

    @Test
    void serve_agentsProveAndAskWhyAndWhyNot_throughTheEngine() throws Exception {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        try (Platform platform = Platform.start(PlatformConfig.of(kb).withEphemeralPorts());
             UserAgent user = user(platform)) {
            user.startAndAwait(Duration.ofSeconds(10));
            newUserA(user);
            await("AskUserName fires for userA", () -> !platform.kb().instancesOf("AskUserName").isEmpty());
            String asked = platform.kb().instancesOf("AskUserName").getFirst().name();

            // The existing AskUserName is an answer of backward chaining, proved by its own existence.
            List<Message.ProofNode> proofs = user.prove("AskUserName", Map.of());
            assertThat(proofs).anySatisfy(p -> assertThat(p.instance()).contains(asked));

            Message.Reason why = user.why(asked);
            assertThat(why.derived()).isTrue();
            assertThat(why.ofClass()).isEqualTo("AskUserName");
            assertThat(why.binding()).containsValue("userA");
            assertThat(why.supports()).extracting(Message.Reason::instance).contains("userA");
            assertThat(why).isEqualTo(EngineLink.reason(platform.engine().why(asked)));

            assertThatThrownBy(() -> user.why("nobody")).isInstanceOf(RequestRefusedException.class)
                    .hasMessageContaining("'nobody'");

            // Why not: AskUserName has fired for userA (refraction); Greeting has no known user to greet.
            Message.NotFired again = user.whyNot("AskUserName", Map.of("mUser", "userA"));
            assertThat(again.bindings()).singleElement().satisfies(b -> {
                assertThat(b.outcome()).isEqualTo("blocked");
                assertThat(b.reason()).isEqualTo("refraction: this binding has already fired");
            });
            assertThat(user.whyNot("Greeting", Map.of()).summary()).isEqualTo("'Greeting' cannot fire: nothing can "
                    + "fill its slot 'mUser' (there is no instance of 'KnownUser').");
            assertThatThrownBy(() -> user.whyNot("User", Map.of())).isInstanceOf(RequestRefusedException.class)
                    .hasMessage("Frame 'User' is not a behavior frame: it has no required instance slot, so the engine "
                            + "never fires it.");
            assertThat(user.isConnected()).isTrue();
        }
    }

    @Test
    void serve_proveWithAnEmptyBinding_isRefused_andTheAgentKeepsItsConnection() throws Exception {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        try (Platform platform = Platform.start(PlatformConfig.of(kb).withEphemeralPorts());
             UserAgent user = user(platform)) {
            user.startAndAwait(Duration.ofSeconds(10));

            // `kicnp agent prove AskUserName mUser=` sends an empty instance name.
            assertThatThrownBy(() -> user.prove("AskUserName", Map.of("mUser", "")))
                    .isInstanceOf(RequestRefusedException.class)
                    .hasMessage("Binding 'mUser' names '', but there is no frame of that name.");
            assertThatThrownBy(() -> user.why("AskUserName")).isInstanceOf(RequestRefusedException.class)
                    .hasMessage("Frame 'AskUserName' is a class; why explains instances only.");

            assertThat(user.isConnected()).isTrue();
            assertThat(user.prove("AskUserName", Map.of())).isNotNull();
        }
    }

    @Test
    void serve_whenTheEngineCancelsAnAction_theRobotIsAskedToStop() throws Exception {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        try (Platform platform = Platform.start(PlatformConfig.of(kb).withEphemeralPorts());
             TalkingRobovie robovie = new TalkingRobovie(platform);
             UserAgent user = user(platform)) {
            Command say = robovie.firstSentenceTo(user);

            assertThat(platform.engine().cancelAction(say.id(), "the user walked away")).isTrue();

            await("Robovie is asked to stop", () -> !robovie.cancels.isEmpty());
            assertThat(robovie.cancels).containsExactly(say.id() + ": the user walked away");
            assertThat(platform.engine().actionStatus(say.id())).contains(org.kicnp.inference.Action.Status.FAILED);
            await("the cancel is in the event log", () -> {
                try {
                    return Files.readAllLines(platform.events().file()).stream()
                            .anyMatch(l -> l.contains("\"event\":\"cancel\"") && l.contains(say.id()));
                } catch (java.io.IOException e) {
                    return false;
                }
            });
        }
    }

    @Test
    void editorStop_ofTheEnginesActionAndOfATeleOperatedCommand_theRobotIsAskedToStopBoth() throws Exception {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        try (Platform platform = Platform.start(PlatformConfig.of(kb).withEphemeralPorts());
             TalkingRobovie robovie = new TalkingRobovie(platform);
             UserAgent user = user(platform)) {
            Command question = robovie.firstSentenceTo(user);

            platform.teleOperation().stop(question.id(), "too long");

            assertThat(platform.engine().actionStatus(question.id()))
                    .contains(org.kicnp.inference.Action.Status.FAILED);
            await("Robovie is asked to stop the engine's question", () -> !robovie.cancels.isEmpty());
            assertThat(robovie.cancels).containsExactly(question.id() + ": too long (asked in the editor)");

            String tele = platform.teleOperation().send("robovie", "say", Map.of("text", "la la la"));
            await("Robovie says the tele-operated line", () -> robovie.says.stream().anyMatch(c -> c.id().equals(tele)));
            platform.teleOperation().stop(tele, "quiet please");
            await("Robovie is asked to stop the tele-operated line", () -> robovie.cancels.size() == 2);
            assertThat(robovie.cancels.get(1)).isEqualTo(tele + ": quiet please (asked in the editor)");
            await("the tele-operated line is over", () -> {
                try {
                    platform.teleOperation().stop(tele, "again");
                    return false;
                } catch (IllegalArgumentException e) {
                    return e.getMessage().equals("No action with the id '" + tele + "' is running.");
                }
            });
            assertThatThrownBy(() -> platform.teleOperation().stop("a999", "nothing"))
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("'a999'");
        }
    }

    /** The user agent "user" of the platform's agent file (not started). */
    private static UserAgent user(Platform platform) {
        return new UserAgent(AgentOptions.of("127.0.0.1", platform.gatewayPort(), "user", AgentKind.USER,
                platform.token("user")));
    }

    /** User A walks in, as a face Robovie has not seen: the stimulus of the paper's first rows. */
    private static void newUserA(UserAgent user) {
        user.assertFrame(Frame.instance("userA", "NewUser")
                .slot(Slot.ofValue("faceText", DataType.STRING, Value.of("0.1,0.2"))).build());
    }

    private static void await(String what, java.util.function.BooleanSupplier done) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!done.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("Timed out waiting until " + what + ".");
            }
            Thread.sleep(20);
        }
    }
}
