package org.kicnp.bench;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import org.HdrHistogram.Histogram;
import org.HdrHistogram.SynchronizedHistogram;
import org.kicnp.core.Change;
import org.kicnp.core.ConditionParser;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.inference.Action;
import org.kicnp.inference.GraalScriptHost;
import org.kicnp.inference.InferenceEngine;
import org.kicnp.inference.ScriptHost;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptRuntime;

/**
 * The two per-stimulus figures of {@code ./kicnp bench inference}, taken on the platform's real path: an engine that
 * runs by itself on its own thread ({@code runOn}) with the sandboxed GraalJS runtime, and a behavior frame
 * {@code Respond(mS: StimA, mR: Responder)} whose {@code onInstantiate} reads two slots of {@code s} and calls
 * {@code sendmsg}. Each sample asserts one stimulus with {@code kb.add} on the caller's thread; the recording action
 * sink stamps the moment the engine hands it the action ({@code stimulus → action}), and a timing wrapper around the
 * script host measures the {@code onInstantiate} call itself; the sink then reports the action ended, as a robot
 * would, so actions do not pile up unfinished. Warm-up samples are discarded. The same is measured
 * first with the engine run by the asserting thread ({@code kb.add} then {@code runToQuiescence()}): the engine's
 * own path without the hand-over between threads, which on a busy machine is mostly the scheduler's.
 */
final class ActionLatencyProbe {
    static final String SCRIPT = "sendmsg(s.mR, 'stimulus ' + s.mS.key + ' for ' + s.mR.name);";

    /** Medians and tails, in microseconds, and whether scripts ran compiled. */
    record Figures(int samples, double scriptMedianMicros, double scriptP99Micros, double latencyMedianMicros,
            double latencyP99Micros, double latencyMaxMicros, double directMedianMicros, double directP99Micros,
            boolean compilerOn, String scriptEngine) { }

    private ActionLatencyProbe() {
    }

    static Figures measure(int warmUp, int samples) throws InterruptedException {
        Histogram scriptNanos = new SynchronizedHistogram(3_600_000_000_000L, 3);
        Histogram directNanos = new Histogram(3_600_000_000_000L, 3);
        Histogram latencyNanos = new Histogram(3_600_000_000_000L, 3);
        try (ScriptRuntime runtime = ScriptRuntime.create(ScriptConfig.defaults())) {
            sample(runtime, Optional.empty(), warmUp, samples, scriptNanos, directNanos);
            ExecutorService engineThread = Executors.newSingleThreadExecutor(r -> {
                Thread t = new Thread(r, "bench-engine");
                t.setDaemon(true);
                return t;
            });
            try {
                sample(runtime, Optional.of(engineThread), warmUp / 4, samples, scriptNanos, latencyNanos);
            } finally {
                engineThread.shutdownNow();
            }
            return new Figures(samples, micros(scriptNanos, 50), micros(scriptNanos, 99), micros(latencyNanos, 50),
                    micros(latencyNanos, 99), latencyNanos.getMaxValue() / 1e3, micros(directNanos, 50),
                    micros(directNanos, 99), runtime.compilerEnabled(), runtime.engineName());
        }
    }

    /**
     * Asserts {@code warmUp + samples} stimuli one at a time into a fresh knowledge base and engine, recording into
     * {@code latency} (and the script timer) only after the warm-up. Without a runner the caller's thread runs the
     * engine right after {@code kb.add}; with one the engine runs by itself there.
     */
    private static void sample(ScriptRuntime runtime, Optional<ExecutorService> runner, int warmUp, int samples,
            Histogram scriptNanos, Histogram latency) throws InterruptedException {
        LinkedBlockingQueue<Long> issued = new LinkedBlockingQueue<>();
        KnowledgeBase kb = KnowledgeBase.create();
        kb.apply(classes());
        TimedScripts timed = new TimedScripts(new GraalScriptHost(runtime), scriptNanos);
        AtomicReference<InferenceEngine> self = new AtomicReference<>();
        InferenceEngine.Builder builder = InferenceEngine.builder(kb).scripts(timed).actionSink((Action a) -> {
            issued.add(System.nanoTime());
            self.get().actionEnded(a.id(), "done"); // as the robot would report it; queued, handled after this firing
        });
        runner.ifPresent(builder::runOn);
        try (InferenceEngine engine = builder.build()) {
            self.set(engine);
            for (int i = 0; i < warmUp + samples; i++) {
                timed.recording = i >= warmUp;
                Frame stimulus = InferenceWorkload.stimulus("x" + i, "StimA", i);
                long start = System.nanoTime();
                kb.add(stimulus);
                if (runner.isEmpty()) {
                    engine.runToQuiescence();
                }
                Long at = issued.poll(10, TimeUnit.SECONDS);
                if (at == null) {
                    throw new IllegalStateException("The engine issued no action within 10 s of stimulus 'x" + i
                            + "'; the script engine is " + runtime.engineName() + ".");
                }
                if (i >= warmUp) {
                    latency.recordValue(Math.max(0, at - start));
                }
            }
        }
    }

    private static double micros(Histogram h, double percentile) {
        return h.getValueAtPercentile(percentile) / 1e3;
    }

    private static List<Change> classes() {
        return List.of(
                new Change.Add(Frame.classFrame("Stimulus").slot(Slot.builder("key", DataType.INTEGER).build()).build()),
                new Change.Add(Frame.classFrame("StimA").parent("Stimulus").build()),
                new Change.Add(Frame.classFrame("Responder").slot(Slot.builder("name", DataType.STRING).build()).build()),
                new Change.Add(Frame.instance("robot1", "Responder").provenance(Provenance.RUNTIME)
                        .slot(Slot.ofValue("name", DataType.STRING, Value.of("Robovie"))).build()),
                new Change.Add(Frame.classFrame("Respond")
                        .slot(Slot.builder("mS", DataType.INSTANCE).argument("StimA").required(true).build())
                        .slot(Slot.builder("mR", DataType.INSTANCE).argument("Responder").required(true)
                                .condition(ConditionParser.parse("COND_ANY")).build())
                        .slot(Slot.ofValue("onInstantiate", DataType.STRING, Value.of(SCRIPT))).build()));
    }

    /** Times each {@code onInstantiate} call of the real script host; other scripts pass through untimed. */
    private static final class TimedScripts implements ScriptHost {
        private final ScriptHost delegate;
        private final Histogram nanos;
        /** Set by the sampling thread between stimuli; read on the engine thread after the hand-over of kb.add. */
        volatile boolean recording;

        TimedScripts(ScriptHost delegate, Histogram nanos) {
            this.delegate = delegate;
            this.nanos = nanos;
        }

        @Override public Object run(String frame, String slot, String source, Map<String, Object> globals) {
            if (!recording || !"onInstantiate".equals(slot)) {
                return delegate.run(frame, slot, source, globals);
            }
            long start = System.nanoTime();
            try {
                return delegate.run(frame, slot, source, globals);
            } finally {
                nanos.recordValue(System.nanoTime() - start);
            }
        }

        @Override public boolean test(String frame, String slot, String source, Map<String, Object> globals) {
            return delegate.test(frame, slot, source, globals);
        }
    }
}
