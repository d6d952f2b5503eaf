package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.RequestRefusedException;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Message;

/**
 * {@code prove} and {@code why} over real sockets: requests that could only give an empty or meaningless answer are
 * refused in words, and a reasoning that throws answers with an error instead of closing the agent's connection.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class GatewayProveWhyTest {
    private static final Duration WAIT = Duration.ofSeconds(10);
    private final KnowledgeBase kb = KnowledgeBase.create();
    private GatewayServer server;
    private UserAgent alice;

    private void start(Reasoning reasoning) {
        start(reasoning, Retraction.removeFrom(kb));
    }

    private void start(Reasoning reasoning, Retraction retraction) {
        kb.add(Frame.classFrame("User").build());
        kb.add(Frame.classFrame("Speech").build());
        kb.add(Frame.classFrame("AskUserName").parent("Speech").slot(Slot.builder("mUser", DataType.INSTANCE)
                .argument("User").required(true).build()).slot(Slot.builder("question", DataType.STRING).build())
                .build());
        kb.add(Frame.instance("userA", "User").build());
        server = GatewayServer.start(GatewayConfig.defaults().withPort(0),
                AgentDirectory.empty().with("alice", "alice-token", AgentKind.USER), kb, FeedbackListener.NONE,
                retraction, reasoning);
        alice = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "alice", AgentKind.USER, "alice-token"));
        alice.startAndAwait(WAIT);
    }

    @AfterEach
    void stop() {
        if (alice != null) {
            alice.close();
        }
        server.close();
    }

    private static void refused(Runnable request, ErrorCode code, String message) {
        assertThatThrownBy(request::run).isInstanceOfSatisfying(RequestRefusedException.class,
                e -> assertThat(e.code()).isEqualTo(code)).hasMessageContaining(message);
    }

    @Test
    void prove_withABindingNamingNoInstance_aClass_orASlotNoAnswerHas_isRefusedNamingIt() {
        start(Reasoning.NONE);

        refused(() -> alice.prove("AskUserName", Map.of("mUser", "nobody")), ErrorCode.UNKNOWN_FRAME,
                "Binding 'mUser' names 'nobody', but there is no frame of that name.");
        refused(() -> alice.prove("AskUserName", Map.of("mUser", "")), ErrorCode.UNKNOWN_FRAME,
                "Binding 'mUser' names '', but there is no frame of that name.");
        refused(() -> alice.prove("AskUserName", Map.of("mUser", "User")), ErrorCode.REJECTED,
                "Binding 'mUser' names 'User', which is a class; a binding names an instance.");
        refused(() -> alice.prove("AskUserName", Map.of("mUsr", "userA")), ErrorCode.REJECTED,
                "Neither class 'AskUserName' nor any class below it has a slot 'mUsr' to bind.");
        refused(() -> alice.prove("AskUserName", Map.of("question", "userA")), ErrorCode.REJECTED,
                "Slot 'question' of class 'AskUserName' holds TYPE_STR values, not instances; a binding names an "
                        + "instance for an instance slot.");
        refused(() -> alice.prove("userA", Map.of()), ErrorCode.REJECTED,
                "Frame 'userA' is an instance; prove takes a class.");
        // A slot of a class below the one asked about is a fine binding: it reaches the reasoning (none here).
        refused(() -> alice.prove("Speech", Map.of("mUser", "userA")), ErrorCode.REJECTED,
                "This server runs no inference engine");
        assertThat(alice.isConnected()).isTrue();
    }

    @Test
    void prove_withABindingNamingAnInstanceOfAClassTheSlotDoesNotHold_isRefusedNamingFrameSlotAndInstance() {
        start(Reasoning.NONE);
        kb.add(Frame.classFrame("KnownUser").parent("User").build());
        kb.add(Frame.instance("taro", "KnownUser").build());
        kb.add(Frame.instance("speech1", "Speech").build());

        refused(() -> alice.prove("AskUserName", Map.of("mUser", "speech1")), ErrorCode.REJECTED,
                "Binding 'mUser' names 'speech1', an instance of 'Speech', but slot 'mUser' of class 'AskUserName' "
                        + "holds instances of 'User' only.");
        refused(() -> alice.prove("Speech", Map.of("mUser", "speech1")), ErrorCode.REJECTED,
                "Binding 'mUser' names 'speech1', an instance of 'Speech', but slot 'mUser' of class 'Speech' "
                        + "holds instances of 'User' only.");
        // An instance of a class below the slot's argument class is a fine binding: it reaches the reasoning.
        refused(() -> alice.prove("AskUserName", Map.of("mUser", "taro")), ErrorCode.REJECTED,
                "This server runs no inference engine");
        assertThat(alice.isConnected()).isTrue();
    }

    @Test
    void why_ofAClass_isRefused_notExplainedAsIfItWereAnInstance() {
        start(Reasoning.NONE);

        refused(() -> alice.why("AskUserName"), ErrorCode.REJECTED,
                "Frame 'AskUserName' is a class; why explains instances only.");
        refused(() -> alice.why("userA"), ErrorCode.REJECTED, "This server runs no inference engine");
        refused(() -> alice.whyNot("AskUserName", Map.of()), ErrorCode.REJECTED, "This server runs no inference engine");
        refused(() -> alice.whyNot("Nope", Map.of()), ErrorCode.UNKNOWN_FRAME, "Nope");
    }

    @Test
    void aReasoningThatThrows_answersWithAnError_andTheConnectionStays() {
        start(new Reasoning() {
            @Override public CompletableFuture<List<Message.ProofNode>> prove(String ofClass, Map<String, String> b) {
                throw new IllegalArgumentException("A frame reference needs a frame name.");
            }

            @Override public CompletableFuture<Message.Reason> why(String instance) {
                throw new IllegalStateException("The inference engine is still starting.");
            }

            @Override public CompletableFuture<Message.NotFired> whyNot(String id, String frame, Map<String, String> b) {
                return CompletableFuture.failedFuture(new IllegalArgumentException("Frame '" + frame
                        + "' is not a behavior frame: it has no required instance slot, so the engine never fires it."));
            }
        });

        refused(() -> alice.prove("AskUserName", Map.of()), ErrorCode.REJECTED, "A frame reference needs a frame name.");
        refused(() -> alice.why("userA"), ErrorCode.REJECTED, "The inference engine is still starting.");
        refused(() -> alice.whyNot("User", Map.of()), ErrorCode.REJECTED, "Frame 'User' is not a behavior frame");
        assertThat(alice.isConnected()).isTrue();
        assertThat(alice.query("User")).hasSize(1);
    }

    @Test
    void aRetractionThatThrows_answersTheDestroyWithAnError_andTheConnectionStays() {
        start(Reasoning.NONE, new Retraction() {
            @Override public void retract(String frame, long expectedRevision) {
            }

            @Override public CompletableFuture<java.util.Set<String>> destroy(String frame) {
                throw new java.util.concurrent.RejectedExecutionException("The engine's thread is shut down.");
            }
        });
        kb.add(Frame.instance("guest", "User").provenance(org.kicnp.core.Provenance.RUNTIME).build());

        refused(() -> alice.destroy("guest"), ErrorCode.REJECTED, "The engine's thread is shut down.");
        assertThat(alice.isConnected()).isTrue();
        assertThat(kb.contains("guest")).isTrue();
    }
}
