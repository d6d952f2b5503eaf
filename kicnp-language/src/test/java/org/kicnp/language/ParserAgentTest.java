package org.kicnp.language;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.gateway.AgentDirectory;
import org.kicnp.gateway.FeedbackListener;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.GatewayServer;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;

/** End to end: a real gateway on 127.0.0.1 (ephemeral port), the parser agent, and a user agent that talks to it. */
class ParserAgentTest {
    private static final Duration WAIT = Duration.ofSeconds(10);
    private static final AgentDirectory AGENTS = AgentDirectory.empty()
            .with("parser", "parser-token", AgentKind.SERVICE)
            .with("alice", "alice-token", AgentKind.USER);

    private final KnowledgeBase kb = KnowledgeBase.create();
    private GatewayServer server;
    private ParserAgent parser;
    private UserAgent alice;

    @BeforeEach
    void start() {
        server = GatewayServer.start(GatewayConfig.defaults().withPort(0), AGENTS, kb, FeedbackListener.NONE);
        parser = new ParserAgent(options("parser", AgentKind.SERVICE), SentenceParser.standard());
        parser.startAndAwait(WAIT);
        alice = new UserAgent(options("alice", AgentKind.USER));
        alice.startAndAwait(WAIT);
    }

    @AfterEach
    void stop() {
        alice.close();
        parser.close();
        server.close();
    }

    @Test
    void register_putsTheLanguageClassesIntoTheKnowledgeBase() {
        assertThat(kb.contains("Utterance")).isTrue();
        assertThat(kb.children("Utterance")).extracting(org.kicnp.core.Frame::name)
                .contains("SaidDrinkRequest", "SaidName", "SaidUnknown");
    }

    @Test
    void utterance_understood_isAssertedAsCaseFrameInstance_andTheSpeakerIsTold() {
        alice.relayTo("parser", ParserAgent.SUBJECT, "Tee, please.");
        Message.Relay reply = awaitReply(0);
        assertThat(reply.subject()).isEqualTo(ParserAgent.UNDERSTOOD);
        String instance = reply.body();
        assertThat(kb.isA(instance, "SaidDrinkRequest")).isTrue();
        assertThat(kb.value(instance, "drink")).contains(Value.of("tea"));
        assertThat(kb.value(instance, "speaker")).contains(Value.of("alice"));
        assertThat(kb.value(instance, "text")).contains(Value.of("Tee, please."));
    }

    @Test
    void utteranceWithNameExpectation_readsABareName() {
        alice.relayTo("parser", ParserAgent.SUBJECT + ":name", "Ken");
        Message.Relay reply = awaitReply(0);
        assertThat(reply.subject()).isEqualTo(ParserAgent.UNDERSTOOD);
        assertThat(kb.value(reply.body(), "name")).contains(Value.of("Ken"));
        assertThat(kb.isA(reply.body(), "SaidName")).isTrue();
    }

    @Test
    void gibberish_getsThePoliteReply_andASaidUnknownInstance_butNoCaseFrame() {
        alice.relayTo("parser", ParserAgent.SUBJECT, "blorf zap");
        Message.Relay reply = awaitReply(0);
        assertThat(reply.subject()).isEqualTo(ParserAgent.SAY_AGAIN);
        assertThat(reply.body()).isEqualTo("Sorry, I didn't catch that. Could you say it again?");
        assertThat(kb.instancesOf("SaidUnknown")).hasSize(1);
        assertThat(kb.instancesOf("Utterance")).hasSize(1);
        String unknown = kb.instancesOf("SaidUnknown").getFirst().name();
        assertThat(kb.value(unknown, "reason")).get().isInstanceOfSatisfying(Value.Str.class,
                s -> assertThat(s.value()).contains("blorf"));
    }

    @Test
    void severalUtterances_eachGetTheirOwnInstance() {
        List<String> said = List.of("My name is Ken", "I'd like a coffee", "Actually, make it tea", "AIBO, sit down");
        said.forEach(s -> alice.relayTo("parser", ParserAgent.SUBJECT, s));
        Message.Relay last = awaitReply(said.size() - 1);
        assertThat(alice.relays()).extracting(Message.Relay::subject).containsOnly(ParserAgent.UNDERSTOOD);
        assertThat(kb.instancesOf("Utterance")).hasSize(4);
        assertThat(kb.value(alice.relays().get(2).body(), "correction")).contains(Value.of("true"));
        assertThat(kb.value(last.body(), "robot")).contains(Value.of("AIBO"));
        assertThat(kb.value(last.body(), "action")).contains(Value.of("sit"));
    }

    @Test
    void longConversation_keepsOnlyTheLatestInstances() {
        int n = ParserAgent.KEEP + 3;
        for (int i = 0; i < n; i++) {
            alice.relayTo("parser", ParserAgent.SUBJECT, i % 2 == 0 ? "Tea, please" : "blorf");
        }
        awaitReply(n - 1);
        assertThat(kb.instancesOf("Utterance")).hasSize(ParserAgent.KEEP);
        assertThat(kb.contains("said-alice-1")).isFalse();
        assertThat(kb.contains("said-alice-" + n)).isTrue();
    }

    @Test
    void veryLongSentence_getsThePoliteReply_andTheParserKeepsUnderstanding() {
        alice.relayTo("parser", ParserAgent.SUBJECT, "blorf ".repeat(100_000));
        assertThat(awaitReply(0).subject()).isEqualTo(ParserAgent.SAY_AGAIN);
        alice.relayTo("parser", ParserAgent.SUBJECT, "Tea, please");
        assertThat(awaitReply(1).subject()).isEqualTo(ParserAgent.UNDERSTOOD);
    }

    private Message.Relay awaitReply(int index) {
        await("reply " + index + " reaches alice", () -> alice.relays().size() > index);
        return alice.relays().get(index);
    }

    private AgentOptions options(String name, AgentKind kind) {
        return AgentOptions.of("127.0.0.1", server.port(), name, kind, name + "-token")
                .withBackoff(Duration.ofMillis(20), Duration.ofMillis(200));
    }

    private static void await(String what, BooleanSupplier condition) {
        long deadline = System.nanoTime() + WAIT.toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("Timed out after " + WAIT + " waiting until " + what + ".");
            }
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new AssertionError("Interrupted waiting until " + what + ".");
            }
        }
    }
}
