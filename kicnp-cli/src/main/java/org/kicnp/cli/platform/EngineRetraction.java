package org.kicnp.cli.platform;

import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicReference;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.UnknownFrameException;
import org.kicnp.gateway.Retraction;
import org.kicnp.inference.InferenceEngine;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Retracts the runtime frames of an agent that left through the inference engine, on the engine's thread: the frame
 * and every instance derived from it go in one batch (a plain removal is refused while a derived instance refers to
 * the frame). The gateway starts before the engine exists; until the engine is {@linkplain #attach attached}, frames
 * are removed from the knowledge base directly.
 */
final class EngineRetraction implements Retraction {
    private static final Logger LOG = LoggerFactory.getLogger(EngineRetraction.class);

    private final Retraction beforeEngine;
    private final Executor engineThread;
    private final AtomicReference<InferenceEngine> engine = new AtomicReference<>();

    EngineRetraction(KnowledgeBase kb, Executor engineThread) {
        this.beforeEngine = Retraction.removeFrom(kb);
        this.engineThread = engineThread;
    }

    void attach(InferenceEngine e) {
        engine.set(e);
    }

    /** An agent's destroy: on the engine's thread, the instance and what rests on it in one batch (or nothing). */
    @Override public CompletableFuture<Set<String>> destroy(String frame) {
        InferenceEngine e = engine.get();
        if (e == null) {
            return Retraction.super.destroy(frame);
        }
        return CompletableFuture.supplyAsync(() -> e.destroy(frame), engineThread);
    }

    @Override public void retract(String frame) {
        InferenceEngine e = engine.get();
        if (e == null) {
            beforeEngine.retract(frame);
            return;
        }
        engineThread.execute(() -> {
            try {
                e.destroy(frame);
            } catch (UnknownFrameException gone) {
                LOG.debug("'{}' was already gone when its agent left.", frame);
            } catch (RuntimeException failed) {
                LOG.warn("Could not retract '{}' after its agent left: {}", frame, failed.getMessage());
            }
        });
    }
}
