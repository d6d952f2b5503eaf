package org.kicnp.cli.platform;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.cli.scenario.ScenarioFiles;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.editor.ChatLine;
import org.kicnp.editor.CommandFeedback;
import org.kicnp.editor.RobotCapabilities;
import org.kicnp.editor.Subscription;
import org.kicnp.language.ParserAgent;
import org.kicnp.language.SentenceParser;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message.Command;

/**
 * The editor's ports as {@code serve} wires them, on the platform in-process over a copy of scenarios/table5 with
 * the real sentence parser agent and a stand-in robot connected over loopback.
 */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class PlatformPortsTest {
    @TempDir
    Path tmp;

    private Platform start() {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        return Platform.start(PlatformConfig.of(kb).withEphemeralPorts());
    }

    private static AgentOptions options(Platform p, String name, AgentKind kind) {
        return AgentOptions.of("127.0.0.1", p.gatewayPort(), name, kind, p.token(name));
    }

    @Test
    void chat_whenAPersonSaysAnUnderstoodSentence_theParserVerdictComesBackAsUnderstood() throws Exception {
        try (Platform platform = start();
             ParserAgent parser = new ParserAgent(options(platform, "parser", AgentKind.SERVICE), SentenceParser.standard())) {
            parser.startAndAwait(Duration.ofSeconds(10));
            LinkedBlockingQueue<ChatLine> lines = new LinkedBlockingQueue<>();
            try (Subscription s = platform.chat().onLine(lines::add)) {
                platform.chat().say("User A", "Tea, please.");
                ChatLine verdict = lines.poll(20, TimeUnit.SECONDS);
                assertThat(verdict).isNotNull();
                assertThat(verdict.kind()).isEqualTo(ChatLine.Kind.UNDERSTOOD);
                assertThat(verdict.speaker()).isEqualTo("User A");
                assertThat(verdict.text()).contains("said-userA-1");
                assertThat(platform.kb().frame("said-userA-1")).isPresent();

                platform.chat().say("User A", "blorf zap");
                ChatLine again = lines.poll(20, TimeUnit.SECONDS);
                assertThat(again).isNotNull();
                assertThat(again.kind()).isEqualTo(ChatLine.Kind.NOT_UNDERSTOOD);
            }
        }
    }

    @Test
    void chat_whenTheEngineMakesRobovieSpeak_theLineComesBackAsARobotLine() throws Exception {
        try (Platform platform = start();
             PlatformTest.RecordingRobot robovie = new PlatformTest.RecordingRobot(options(platform, "robovie", AgentKind.ROBOT));
             UserAgent user = new UserAgent(options(platform, "user", AgentKind.USER))) {
            robovie.startAndAwait(Duration.ofSeconds(10));
            user.startAndAwait(Duration.ofSeconds(10));
            LinkedBlockingQueue<ChatLine> lines = new LinkedBlockingQueue<>();
            try (Subscription s = platform.chat().onLine(lines::add)) {
                user.assertFrame(Frame.instance("userA", "NewUser")
                        .slot(Slot.ofValue("faceText", DataType.STRING, Value.of("0.1,0.2"))).build());
                ChatLine line = lines.poll(20, TimeUnit.SECONDS);
                assertThat(line).isNotNull();
                assertThat(line.kind()).isEqualTo(ChatLine.Kind.ROBOT);
                assertThat(line.speaker()).isEqualTo("Robovie");
                assertThat(line.text()).isEqualTo("How are you! I have never seen you before. What is your name?");
            }
        }
    }

    @Test
    void chat_aNameSaidAlone_isNotUnderstoodUntilRobovieAsksForIt_thenItIs() throws Exception {
        try (Platform platform = start();
             ParserAgent parser = new ParserAgent(options(platform, "parser", AgentKind.SERVICE), SentenceParser.standard());
             PlatformTest.RecordingRobot robovie = new PlatformTest.RecordingRobot(options(platform, "robovie", AgentKind.ROBOT));
             UserAgent user = new UserAgent(options(platform, "user", AgentKind.USER))) {
            parser.startAndAwait(Duration.ofSeconds(10));
            robovie.startAndAwait(Duration.ofSeconds(10));
            user.startAndAwait(Duration.ofSeconds(10));
            LinkedBlockingQueue<ChatLine> lines = new LinkedBlockingQueue<>();
            try (Subscription s = platform.chat().onLine(lines::add)) {
                platform.chat().say("User A", "Ken.");
                assertThat(nextOf(lines, "User A").kind()).as("no question was asked").isEqualTo(ChatLine.Kind.NOT_UNDERSTOOD);

                user.assertFrame(Frame.instance("userA", "NewUser")
                        .slot(Slot.ofValue("faceText", DataType.STRING, Value.of("0.1,0.2"))).build());
                assertThat(nextOf(lines, "Robovie").text()).endsWith("What is your name?");
                platform.chat().say("User A", "Ken.");
                ChatLine verdict = nextOf(lines, "User A");
                assertThat(verdict.kind()).as(verdict.text()).isEqualTo(ChatLine.Kind.UNDERSTOOD);
                assertThat(verdict.text()).startsWith("SaidName");
            }
        }
    }

    /** The next line of {@code speaker}, skipping the others' (within 20 s). */
    private static ChatLine nextOf(LinkedBlockingQueue<ChatLine> lines, String speaker) throws InterruptedException {
        while (true) {
            ChatLine line = lines.poll(20, TimeUnit.SECONDS);
            assertThat(line).as("a line of " + speaker).isNotNull();
            if (line.speaker().equals(speaker)) {
                return line;
            }
        }
    }

    @Test
    void chat_whenTheSpeakerHasNoAgentToken_refusesTheLine() {
        try (Platform platform = start()) {
            assertThatThrownBy(() -> platform.chat().say("Mallory", "Tea, please."))
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("'Mallory'");
            assertThatThrownBy(() -> platform.chat().say("User A", " "))
                    .isInstanceOf(IllegalArgumentException.class);
        }
    }

    @Test
    void chat_asASpeakerWhoseAgentIsConnectedElsewhere_refusesTheLine_andLeavesThatConnectionAlone() throws Exception {
        try (Platform platform = start();
             UserAgent terminal = new UserAgent(options(platform, "userA", AgentKind.USER))) {
            terminal.startAndAwait(Duration.ofSeconds(10));

            assertThatThrownBy(() -> platform.chat().say("User A", "Tea, please."))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("'User A' is connected already as agent 'userA' (in the demo, at its terminal): "
                            + "speak there, or here as another person.");
            // Not superseded: the terminal's agent still talks to the server.
            assertThat(terminal.isConnected()).isTrue();
            assertThat(terminal.query("Robot")).isNotEmpty();
            assertThat(platform.gateway().registeredAgents()).contains("userA");
        }
    }

    @Test
    void teleOperation_whenACommandIsSent_theRobotReceivesItAndItsFeedbackAndJudgementFollow() throws Exception {
        try (Platform platform = start();
             PlatformTest.RecordingRobot scout = new PlatformTest.RecordingRobot(options(platform, "scout", AgentKind.ROBOT))) {
            scout.startAndAwait(Duration.ofSeconds(10));
            assertThat(platform.teleOperation().robots()).extracting(RobotCapabilities::name).containsExactly("scout");
            assertThat(platform.teleOperation().robots().get(0).actions())
                    .extracting(RobotCapabilities.ActionSpec::name).contains("go_to");
            LinkedBlockingQueue<CommandFeedback> feedback = new LinkedBlockingQueue<>();
            try (Subscription s = platform.teleOperation().onFeedback(feedback::add)) {
                String id = platform.teleOperation().send("scout", "go_to", Map.of("x", "1.5", "y", "2.0"));

                Command received = scout.commands.poll(20, TimeUnit.SECONDS);
                while (received != null && !received.id().equals(id)) { // commands the engine issued itself
                    received = scout.commands.poll(20, TimeUnit.SECONDS);
                }
                assertThat(received).isNotNull();
                assertThat(received.args()).containsEntry("x", "1.5");
                CommandFeedback started = next(feedback, id);
                CommandFeedback ended = next(feedback, id);
                assertThat(started).isNotNull();
                assertThat(ended).isNotNull();
                assertThat(started.commandId()).isEqualTo(id);
                assertThat(started.status()).isEqualTo(CommandFeedback.Status.STARTED);
                assertThat(ended.status()).isEqualTo(CommandFeedback.Status.ENDED);
                assertThat(ended.detail()).isEqualTo("said it");

                platform.teleOperation().markWrong(id, "wrong corner");
                String name = "WrongAction-" + id;
                assertThat(platform.kb().isA(name, "WrongAction")).isTrue();
                assertThat(platform.kb().value(name, "robot")).contains(Value.of("scout"));
                assertThat(platform.kb().value(name, "name")).contains(Value.of("go_to"));
                assertThat(platform.kb().value(name, "reason")).contains(Value.of("wrong corner"));
                assertThat(platform.kb().value(name, "judgedBy")).contains(Value.of("editor"));
            }
        }
    }

    private static CommandFeedback next(LinkedBlockingQueue<CommandFeedback> feedback, String id)
            throws InterruptedException {
        CommandFeedback f = feedback.poll(20, TimeUnit.SECONDS);
        while (f != null && !f.commandId().equals(id)) {
            f = feedback.poll(20, TimeUnit.SECONDS);
        }
        return f;
    }

    @Test
    void teleOperation_whenTheRobotOrIdIsUnknown_refuses() {
        try (Platform platform = start()) {
            assertThatThrownBy(() -> platform.teleOperation().send("r2d2", "go_to", Map.of()))
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("'r2d2'");
            assertThatThrownBy(() -> platform.teleOperation().send("scout", "go_to", Map.of("x", "1", "y", "2")))
                    .isInstanceOf(IllegalStateException.class).hasMessageContaining("not connected");
            assertThatThrownBy(() -> platform.teleOperation().markWrong("nope-1", "why"))
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("'nope-1'");
        }
    }
}
