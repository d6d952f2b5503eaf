package org.kicnp.cli.platform;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Function;
import org.kicnp.core.Value;
import org.kicnp.gateway.Reasoning;
import org.kicnp.inference.Derivation;
import org.kicnp.inference.Explanation;
import org.kicnp.inference.InferenceEngine;
import org.kicnp.inference.Proof;
import org.kicnp.protocol.Message;

/**
 * The inference engine's backward chaining and explanations for the gateway's agents ({@code prove}, {@code why}),
 * run on the engine's thread so that a gateway I/O thread never waits for the engine, and turned into the protocol's
 * records. The gateway starts before the engine; until the engine is {@linkplain #attach attached} both are refused.
 */
final class EngineReasoning implements Reasoning {
    private final Executor engineThread;
    private final AtomicReference<InferenceEngine> engine = new AtomicReference<>();

    EngineReasoning(Executor engineThread) {
        this.engineThread = engineThread;
    }

    void attach(InferenceEngine e) {
        engine.set(e);
    }

    @Override public CompletableFuture<List<Message.ProofNode>> prove(String ofClass, Map<String, String> bindings) {
        return onEngine(e -> {
            // On the engine's thread: a binding that is no frame reference fails this answer, not the connection.
            Map<String, Value> refs = new LinkedHashMap<>();
            bindings.forEach((slot, instance) -> refs.put(slot, Value.ref(instance)));
            return e.prove(ofClass, refs).stream().map(EngineReasoning::node).toList();
        });
    }

    @Override public CompletableFuture<Message.Reason> why(String instance) {
        return onEngine(e -> reason(e.why(instance)));
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

    static Message.Reason reason(Explanation e) {
        return switch (e) {
            case Explanation.Asserted a -> new Message.Reason(a.instance(), a.className(), false, Map.of(), List.of(),
                    List.of());
            case Explanation.Derived d -> {
                Derivation how = d.derivation();
                yield new Message.Reason(how.instance(), how.frame(), true, how.binding(), how.conditions().stream()
                        .map(c -> c.slot() + ": " + c.condition() + " = " + c.value()).toList(),
                        d.supports().stream().map(EngineReasoning::reason).toList());
            }
        };
    }
}
