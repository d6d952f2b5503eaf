package org.kicnp.bench;

import java.lang.ref.Reference;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.InstanceShape;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.inference.EngineOptions;
import org.kicnp.inference.InferenceEngine;

/**
 * One timed run of the workload in K-ICNP: a fresh knowledge base with the classes and a fresh engine; the timer
 * covers asserting the N stimuli (one batch) and {@code runToQuiescence()}, each firing creating a validated
 * instance frame in the knowledge base.
 */
final class KicnpInferenceRun {
    private static final Frame[] NOTHING_AT_HAND = new Frame[0];

    private KicnpInferenceRun() {
    }

    static EngineResult run(InferenceWorkload w) {
        return run(w, KnowledgeBase.create(), w.kicnpStimuli());
    }

    private static EngineResult run(InferenceWorkload w, KnowledgeBase kb, List<Change> stimuli) {
        kb.apply(w.kicnpClasses());
        try (InferenceEngine engine = engine(kb, w)) {
            long cpu = EngineResult.threadCpuNanos();
            long start = System.nanoTime();
            kb.apply(stimuli);
            long fired = engine.runToQuiescence();
            long nanos = System.nanoTime() - start;
            return new EngineResult(fired, nanos, EngineResult.threadCpuNanos() - cpu);
        }
    }

    /**
     * The heap one run of {@code w} keeps reachable when it is over: a fresh knowledge base with the classes and a fresh
     * engine, the stimuli asserted and the engine run to quiescence, read with {@link HeapMeter} before and after. The
     * stimuli's frames are made before the first reading, as Drools' facts are ({@link DroolsInferenceRun#retained}),
     * so what is counted is each engine's own: K-ICNP's knowledge base (frames derived, indexes, nodes) and engine
     * (fact records, memories, truth-maintenance records, explanations).
     */
    static long retained(InferenceWorkload w) {
        List<Change> stimuli = w.kicnpStimuli();
        long before = HeapMeter.usedAfterGc();
        KnowledgeBase kb = KnowledgeBase.create();
        kb.apply(w.kicnpClasses());
        try (InferenceEngine engine = engine(kb, w)) {
            kb.apply(stimuli);
            engine.runToQuiescence();
            long after = HeapMeter.usedAfterGc();
            Reference.reachabilityFence(engine);
            Reference.reachabilityFence(kb);
            Reference.reachabilityFence(stimuli);
            return after - before;
        }
    }

    /** A fresh engine on {@code kb} whose firing limit leaves the workload's firings room (twice as many). */
    private static InferenceEngine engine(KnowledgeBase kb, InferenceWorkload w) {
        int limit = (int) Math.min(Integer.MAX_VALUE - 1, Math.max(10_000, w.expectedFirings() * 2));
        return InferenceEngine.builder(kb).options(EngineOptions.defaults().withMaxFirings(limit)).build();
    }

    /**
     * What one (untimed) run of {@code w} stored: its stimuli and the instances the engine derived, in the order it
     * committed them. The derived frames refer to the stimuli's and each other's very name strings, as in a run.
     */
    record Stored(List<Change> stimuli, List<Frame> derived) {
    }

    static Stored stored(InferenceWorkload w) {
        KnowledgeBase kb = KnowledgeBase.create();
        List<Change> stimuli = w.kicnpStimuli();
        run(w, kb, stimuli);
        return new Stored(stimuli,
                kb.frames().stream().filter(f -> f.isInstance() && kb.isA(f.name(), "Derived")).toList());
    }

    /**
     * The knowledge base's own share of a run, with no engine: into a fresh knowledge base with the same classes, the
     * timer covers asserting the same N stimuli (one batch) and then adding the derived instances one at a time, as
     * the engine commits each (through its frame's prepared shape: validated, indexed, its change event made; with no
     * frames at hand, so each value's name is looked up). No matching, agenda, truth maintenance or
     * explanation. "Firings" is the number of instances added this way.
     */
    static EngineResult storeOnly(InferenceWorkload w, Stored stored) {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.apply(w.kicnpClasses());
        // The engine's add: through each behavior frame's prepared shape, its slots' values in the shape's order.
        Map<String, InstanceShape> shapes = new HashMap<>();
        List<Frame> derived = stored.derived();
        InstanceShape[] shapeOf = new InstanceShape[derived.size()];
        Value[][] valuesOf = new Value[derived.size()][];
        for (int i = 0; i < shapeOf.length; i++) {
            Frame f = derived.get(i);
            shapeOf[i] = shapes.computeIfAbsent(f.parent().orElseThrow(),
                    c -> InstanceShape.of(c, f.slots().stream().map(Slot::name).toList()));
            valuesOf[i] = f.slots().stream().map(s -> s.value().orElseThrow()).toArray(Value[]::new);
        }
        long cpu = EngineResult.threadCpuNanos();
        long start = System.nanoTime();
        kb.apply(stored.stimuli());
        for (int i = 0; i < shapeOf.length; i++) {
            kb.addInstance(shapeOf[i], derived.get(i).name(), valuesOf[i], NOTHING_AT_HAND);
        }
        long nanos = System.nanoTime() - start;
        return new EngineResult(stored.derived().size(), nanos, EngineResult.threadCpuNanos() - cpu);
    }
}
