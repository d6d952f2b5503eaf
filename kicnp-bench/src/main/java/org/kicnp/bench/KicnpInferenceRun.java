package org.kicnp.bench;

import java.util.List;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.inference.EngineOptions;
import org.kicnp.inference.InferenceEngine;

/**
 * One timed run of the workload in K-ICNP: a fresh knowledge base with the classes and a fresh engine; the timer
 * covers asserting the N stimuli (one batch) and {@code runToQuiescence()}, each firing creating a validated
 * instance frame in the knowledge base.
 */
final class KicnpInferenceRun {
    private KicnpInferenceRun() {
    }

    static EngineResult run(InferenceWorkload w) {
        return run(w, KnowledgeBase.create());
    }

    private static EngineResult run(InferenceWorkload w, KnowledgeBase kb) {
        kb.apply(w.kicnpClasses());
        long expected = w.expectedFirings();
        int limit = (int) Math.min(Integer.MAX_VALUE - 1, Math.max(10_000, expected * 2));
        List<Change> stimuli = w.kicnpStimuli();
        try (InferenceEngine engine = InferenceEngine.builder(kb)
                .options(EngineOptions.defaults().withMaxFirings(limit)).build()) {
            long cpu = EngineResult.threadCpuNanos();
            long start = System.nanoTime();
            kb.apply(stimuli);
            long fired = engine.runToQuiescence();
            long nanos = System.nanoTime() - start;
            return new EngineResult(fired, nanos, EngineResult.threadCpuNanos() - cpu);
        }
    }

    /** The instances a run of {@code w} derives, in the order the engine committed them (an untimed run). */
    static List<Frame> derivedInstances(InferenceWorkload w) {
        KnowledgeBase kb = KnowledgeBase.create();
        run(w, kb);
        return kb.frames().stream().filter(f -> f.isInstance() && kb.isA(f.name(), "Derived")).toList();
    }

    /**
     * The knowledge base's own share of a run, with no engine: into a fresh knowledge base with the same classes, the
     * timer covers asserting the same N stimuli (one batch) and then adding {@code derived} one at a time, as the
     * engine commits each derived instance (validated, indexed, its change event published). No matching, agenda,
     * truth maintenance or explanation. "Firings" is the number of instances added this way.
     */
    static EngineResult storeOnly(InferenceWorkload w, List<Frame> derived) {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.apply(w.kicnpClasses());
        List<Change> stimuli = w.kicnpStimuli();
        long cpu = EngineResult.threadCpuNanos();
        long start = System.nanoTime();
        kb.apply(stimuli);
        for (Frame f : derived) {
            kb.add(f);
        }
        long nanos = System.nanoTime() - start;
        return new EngineResult(derived.size(), nanos, EngineResult.threadCpuNanos() - cpu);
    }
}
