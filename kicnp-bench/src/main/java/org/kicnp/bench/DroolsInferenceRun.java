package org.kicnp.bench;

import java.lang.ref.Reference;
import java.util.ArrayList;
import java.util.List;
import org.drools.model.codegen.ExecutableModelProject;
import org.kie.api.KieBase;
import org.kie.api.definition.type.FactType;
import org.kie.api.io.ResourceType;
import org.kie.api.runtime.KieSession;
import org.kie.internal.utils.KieHelper;

/**
 * The workload in Drools: the DRL of {@link InferenceWorkload#drl()} compiled once, at bench run time, to Drools'
 * executable model ({@link ExecutableModelProject}: DRL → generated Java → compiled in memory), then one fresh
 * {@link KieSession} per run. The timer covers inserting the N stimulus facts and {@code fireAllRules()}; the facts
 * are created (through the declared types' {@link FactType}s) before the timer starts, as K-ICNP's frames are.
 */
final class DroolsInferenceRun {
    private final KieBase kieBase;
    private final FactType[] stimulusTypes = new FactType[InferenceWorkload.GROUP];

    private DroolsInferenceRun(KieBase kieBase) {
        this.kieBase = kieBase;
        for (int i = 0; i < InferenceWorkload.GROUP; i++) {
            stimulusTypes[i] = type(InferenceWorkload.stimulusClass(i));
        }
    }

    /** Compiles the workload's DRL (plain {@code insert}) with the executable model; takes a few seconds. */
    static DroolsInferenceRun compile() {
        return compile(false);
    }

    /** As {@link #compile()}; with {@code logical}, the rules insert derived facts with {@code insertLogical}. */
    static DroolsInferenceRun compile(boolean logical) {
        KieBase kb = new KieHelper().addContent(InferenceWorkload.drl(logical), ResourceType.DRL)
                .build(ExecutableModelProject.class);
        return new DroolsInferenceRun(kb);
    }

    private FactType type(String name) {
        FactType t = kieBase.getFactType(InferenceWorkload.DRL_PACKAGE, name);
        if (t == null) {
            throw new IllegalStateException("Drools compiled the workload without the declared type '" + name + "'.");
        }
        return t;
    }

    EngineResult run(InferenceWorkload w) {
        List<Object> facts = stimuli(w);
        KieSession session = kieBase.newKieSession();
        try {
            long cpu = EngineResult.threadCpuNanos();
            long start = System.nanoTime();
            long fired = insertAndFire(session, facts);
            long nanos = System.nanoTime() - start;
            return new EngineResult(fired, nanos, EngineResult.threadCpuNanos() - cpu);
        } finally {
            session.dispose();
        }
    }

    /**
     * The heap one run of {@code w} keeps reachable before its session is disposed, read with {@link HeapMeter} before
     * the session is made (the stimulus facts made already) and after {@code fireAllRules()}: the session's network
     * memories, agenda records and derived facts ({@link KicnpInferenceRun#retained} counts the same for K-ICNP).
     */
    long retained(InferenceWorkload w) {
        List<Object> facts = stimuli(w);
        long before = HeapMeter.usedAfterGc();
        KieSession session = kieBase.newKieSession();
        try {
            insertAndFire(session, facts);
            long after = HeapMeter.usedAfterGc();
            Reference.reachabilityFence(facts);
            return after - before;
        } finally {
            session.dispose();
        }
    }

    /** Inserts the facts and fires to quiescence; returns the firings. */
    private static long insertAndFire(KieSession session, List<Object> facts) {
        for (Object fact : facts) {
            session.insert(fact);
        }
        return session.fireAllRules();
    }

    /** The N stimulus facts, made through the declared types. */
    private List<Object> stimuli(InferenceWorkload w) {
        List<Object> facts = new ArrayList<>(w.n());
        try {
            for (int i = 0; i < w.n(); i++) {
                FactType t = stimulusTypes[i % InferenceWorkload.GROUP];
                Object fact = t.newInstance();
                t.set(fact, "key", InferenceWorkload.key(i));
                facts.add(fact);
            }
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("Could not create a Drools stimulus fact: " + e.getMessage(), e);
        }
        return facts;
    }
}
