package org.kicnp.cli.platform;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Function;
import org.kicnp.core.Change;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.StaleRevisionException;
import org.kicnp.core.UnknownFrameException;
import org.kicnp.core.Value;
import org.kicnp.gateway.Reasoning;
import org.kicnp.gateway.Retraction;
import org.kicnp.inference.Derivation;
import org.kicnp.inference.Explanation;
import org.kicnp.inference.InferenceEngine;
import org.kicnp.inference.QuestionTooBroadException;
import org.kicnp.inference.Proof;
import org.kicnp.inference.WhyNot;
import org.kicnp.protocol.Message;

/**
 * The gateway's two ports to the inference engine, each run on the engine's thread so that a gateway I/O thread
 * never waits for the engine:
 * <ul>
 *   <li>{@link Retraction}: the runtime frames of an agent that left, and an instance an agent destroys, go through
 *   the engine — the frame and every instance derived from it in one batch (a plain removal is refused while a derived
 *   instance refers to the frame);</li>
 *   <li>{@link Reasoning}: backward chaining and explanations ({@code prove}, {@code why}, {@code why_not}), turned into the
 *   protocol's records.</li>
 * </ul>
 * The gateway starts before the engine exists; until the engine is {@linkplain #attach attached}, frames are removed
 * from the knowledge base directly and reasoning is refused.
 */
final class EngineLink implements Retraction, Reasoning {
    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(EngineLink.class);

    private final Retraction beforeEngine;
    private final Executor engineThread;
    private final AtomicReference<InferenceEngine> engine = new AtomicReference<>();

    EngineLink(KnowledgeBase kb, Executor engineThread) {
        this.beforeEngine = Retraction.removeFrom(kb);
        this.engineThread = engineThread;
    }

    void attach(InferenceEngine e) {
        engine.set(e);
    }

    // ---- Retraction ----

    /** An agent's destroy: on the engine's thread, the instance and what rests on it in one batch (or nothing). */
    @Override public CompletableFuture<Set<String>> destroy(String frame) {
        InferenceEngine e = engine.get();
        if (e == null) {
            return Retraction.super.destroy(frame);
        }
        return CompletableFuture.supplyAsync(() -> e.destroy(frame), engineThread);
    }

    @Override public void retract(String frame, long expectedRevision) {
        InferenceEngine e = engine.get();
        if (e == null) {
            beforeEngine.retract(frame, expectedRevision);
            return;
        }
        String reason = expectedRevision == Change.ANY_REVISION ? "retracted when its agent left"
                : "retracted as stale (no newer version came in its time to live)";
        engineThread.execute(() -> {
            try {
                e.destroy(frame, expectedRevision, reason);
            } catch (UnknownFrameException gone) {
                LOG.debug("'{}' was already gone when it was to be {}.", frame, reason);
            } catch (StaleRevisionException newer) {
                LOG.debug("'{}' changed before it was {}; the newer version stays.", frame, reason);
            } catch (RuntimeException failed) {
                LOG.warn("Could not retract '{}' ({}): {}", frame, reason, failed.getMessage());
            }
        });
    }

    // ---- Reasoning ----

    @Override public CompletableFuture<List<Message.ProofNode>> prove(String ofClass, Map<String, String> bindings) {
        return onEngine(e -> {
            // On the engine's thread: a binding that is no frame reference fails this answer, not the connection.
            Map<String, Value> refs = new LinkedHashMap<>();
            bindings.forEach((slot, instance) -> refs.put(slot, Value.ref(instance)));
            try {
                return e.prove(ofClass, refs).stream().map(EngineLink::node).toList();
            } catch (QuestionTooBroadException broad) { // a refusal in words, as the other questions' are
                throw new IllegalArgumentException(broad.getMessage(), broad);
            }
        });
    }

    @Override public CompletableFuture<Message.Reason> why(String instance) {
        return onEngine(e -> reason(e.why(instance)));
    }

    @Override public CompletableFuture<Message.NotFired> whyNot(String id, String frame,
                                                                Map<String, String> bindings) {
        return onEngine(e -> notFired(id, e.whyNot(frame, bindings)));
    }

    private <T> CompletableFuture<T> onEngine(Function<InferenceEngine, T> work) {
        InferenceEngine e = engine.get();
        if (e == null) {
            return CompletableFuture.failedFuture(new IllegalStateException("The inference engine is still starting."));
        }
        return CompletableFuture.supplyAsync(() -> work.apply(e), engineThread);
    }

    static Message.ProofNode node(Proof p) {
        return switch (p) {
            case Proof.Exists e -> new Message.ProofNode(e.className(), Optional.of(e.instance()), Map.of(), List.of());
            case Proof.Derivable d -> {
                Map<String, Message.ProofNode> slots = new LinkedHashMap<>();
                d.slots().forEach((slot, sub) -> slots.put(slot, node(sub)));
                yield new Message.ProofNode(d.frame(), Optional.empty(), slots, d.assumptions());
            }
        };
    }

    static Message.NotFired notFired(String id, WhyNot w) {
        return new Message.NotFired(id, w.frame(), w.summary(), w.slots().stream().map(s -> new Message.SlotCandidates(
                s.slot(), s.argument(), s.condition(), s.candidates(), s.rejected(), s.candidateCount(),
                s.rejectedCount())).toList(),
                w.bindings().stream().map(v -> new Message.BindingOutcome(v.binding(),
                        v.outcome().name().toLowerCase(Locale.ROOT), v.reason())).toList(), w.truncated());
    }

    static Message.Reason reason(Explanation e) {
        return switch (e) {
            case Explanation.Asserted a -> new Message.Reason(a.instance(), a.className(), false, Map.of(), List.of(),
                    List.of());
            case Explanation.Derived d -> {
                Derivation how = d.derivation();
                yield new Message.Reason(how.instance(), how.frame(), true, how.binding(), how.conditions().stream()
                        .map(c -> c.slot() + ": " + c.condition() + " = " + c.value()).toList(),
                        d.supports().stream().map(EngineLink::reason).toList());
            }
        };
    }
}
