package org.kicnp.gateway;

import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import org.kicnp.protocol.Message;

/**
 * Backward chaining and explanations for agents ({@code prove}, {@code why}): in the platform, the inference
 * engine's. Called on a gateway I/O thread: return at once and complete when the answer is ready. A failure completes
 * exceptionally: {@link org.kicnp.core.UnknownFrameException} for a class or instance the knowledge base lacks, any
 * other exception with the sentence to answer.
 */
public interface Reasoning {
    /** The answers to "which instances of this class are there or could there be", each with its proof. */
    CompletableFuture<List<Message.ProofNode>> prove(String ofClass, Map<String, String> bindings);

    /** Why an instance exists, back to the stimuli. */
    CompletableFuture<Message.Reason> why(String instance);

    /**
     * Why a behavior frame has not fired, with the slots {@code bindings} names held (slot → instance): the answer
     * to the request {@code id}. Refused (a failed future whose message is a sentence) when the frame is not a
     * behavior frame or a binding names a slot it does not require.
     */
    CompletableFuture<Message.NotFired> whyNot(String id, String frame, Map<String, String> bindings);

    /** A gateway without an inference engine: each is refused, saying so. */
    Reasoning NONE = new Reasoning() {
        @Override public CompletableFuture<List<Message.ProofNode>> prove(String ofClass, Map<String, String> b) {
            return CompletableFuture.failedFuture(none());
        }

        @Override public CompletableFuture<Message.Reason> why(String instance) {
            return CompletableFuture.failedFuture(none());
        }

        @Override public CompletableFuture<Message.NotFired> whyNot(String id, String frame,
                                                                    Map<String, String> bindings) {
            return CompletableFuture.failedFuture(none());
        }

        private static IllegalStateException none() {
            return new IllegalStateException("This server runs no inference engine, so it cannot prove or explain.");
        }
    };
}
