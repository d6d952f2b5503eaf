package org.kicnp.bench;

import java.util.List;
import org.kicnp.core.Change;
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
        KnowledgeBase kb = KnowledgeBase.create();
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
}
