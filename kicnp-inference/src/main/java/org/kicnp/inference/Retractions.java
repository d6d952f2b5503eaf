package org.kicnp.inference;

import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.Function;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.UnknownFrameException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Takes instances out of the knowledge base together with every live instance that rests on them, in one batch, and
 * traces each with its reason. Kept apart so that every retraction (a derivation that no longer holds, a failed
 * {@code onInstantiate}, an edited frame, a destroy through the engine) goes the same way, whoever asks for it.
 */
final class Retractions {
    /** Logged under the forward chainer's name, where these lines were before they moved here. */
    private static final Logger LOG = LoggerFactory.getLogger(ForwardChainer.class);
    private final KnowledgeBase kb;
    private final Supports supports;
    private final DerivationCheck check;
    private final Consumer<TraceEvent> tracer;

    Retractions(KnowledgeBase kb, Supports supports, DerivationCheck check, Consumer<TraceEvent> tracer) {
        this.kb = kb;
        this.supports = supports;
        this.check = check;
        this.tracer = tracer;
    }

    /**
     * Retracts a derived instance, with what rests on it, when a slot of its derivation no longer holds; its binding
     * may then fire again. {@code reason} words the retraction from the failing slot.
     */
    void retractIfFailing(String instance, Derivation d, Function<String, String> reason) {
        check.failingSlot(d).ifPresent(slot -> {
            check.unmarkFired(d);
            Set<String> all = new LinkedHashSet<>(List.of(instance));
            all.addAll(supports.closure(instance));
            removeQuietly(all, reason.apply(slot));
        });
    }

    /** Removes an instance and every live instance resting on it, in one batch; returns the names. */
    Set<String> destroyNow(String instance, String reason) {
        return destroyNow(instance, reason, Change.ANY_REVISION);
    }

    /** As {@link #destroyNow(String, String)}, only while the instance is at {@code expectedRevision}. */
    Set<String> destroyNow(String instance, String reason, long expectedRevision) {
        Frame target = kb.frame(instance).orElseThrow(() -> new UnknownFrameException(instance));
        if (!target.isInstance()) {
            throw new KnowledgeException("Frame '" + instance + "' is a class frame; only instances can be destroyed.");
        }
        Set<String> all = new LinkedHashSet<>(List.of(instance));
        all.addAll(supports.closure(instance));
        all.removeIf(n -> !kb.contains(n));
        kb.apply(all.stream().map(n -> new Change.Remove(n, n.equals(instance) ? expectedRevision
                : Change.ANY_REVISION)).toList());
        all.forEach(n -> trace(new TraceEvent.Retracted(n, n.equals(instance) ? reason
                : "it rests on '" + instance + "', which was " + reason)));
        return all;
    }

    /** Retracts the instances that are still there, in one batch, tracing each with the reason; a refusal is logged. */
    void removeQuietly(Collection<String> names, String reason) {
        List<String> live = names.stream().filter(kb::contains).toList();
        if (live.isEmpty()) {
            return;
        }
        try {
            kb.apply(live.stream().map(Change.Remove::new).toList());
            live.forEach(n -> trace(new TraceEvent.Retracted(n, reason)));
        } catch (KnowledgeException e) {
            LOG.error("Could not retract {} ({}): {}", live, reason, e.getMessage());
        }
    }

    private void trace(TraceEvent e) {
        tracer.accept(e);
    }
}
