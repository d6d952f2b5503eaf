package org.kicnp.script;

import java.util.Arrays;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Measures one typical {@code onInstantiate} run: the script reads two slots of {@code s} and calls the host
 * function {@code Sendmsg}, with fresh globals each call as the inference engine binds them. Prints the median
 * and 90th percentile in microseconds after a warm-up, and whether the Graal compiler was active.
 *
 * <p>Usage: {@code java [graal flags] -cp ... org.kicnp.script.ScriptBenchmark [runs] [warm-up runs] [loop]}; the flags
 * come from {@code scripts/graal-opts.sh}. This is a command-line tool, so it prints to standard output.
 */
public final class ScriptBenchmark {

    /** The measured script: two slot reads and one host call, like the paper's Table 4 demon. */
    static final String SCRIPT = "Sendmsg(s.mMouth, 'Hi ' + s.mUser + '! Nice to meet you. Welcome to visit my room!');";

    /** A heavier variant with a loop, where compiled code matters more than the cost of entering a context. */
    static final String LOOP_SCRIPT = "let n = 0; for (let i = 0; i < 1000; i++) { n += (i * 7) % 13; }"
            + " Sendmsg(s.mMouth, s.mUser + ' scored ' + n);";

    private ScriptBenchmark() {
    }

    public static void main(String[] args) {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 50_000;
        int warmUp = args.length > 1 ? Integer.parseInt(args[1]) : 300_000;
        boolean loop = args.length > 2 && args[2].equals("loop");
        AtomicLong sent = new AtomicLong();
        try (ScriptRuntime runtime = ScriptRuntime.create(ScriptConfig.defaults())) {
            CompiledScript script = runtime.compile(new ScriptId("Greeting", "onInstantiate"),
                    loop ? LOOP_SCRIPT : SCRIPT);
            for (int i = 0; i < warmUp; i++) {
                runOnce(runtime, script, sent, i);
            }
            long[] micros = new long[runs];
            for (int i = 0; i < runs; i++) {
                long start = System.nanoTime();
                runOnce(runtime, script, sent, i);
                micros[i] = System.nanoTime() - start;
            }
            Arrays.sort(micros);
            System.out.printf(Locale.ROOT, "%s run: median %.1f us, p90 %.1f us over %d runs after %d warm-up runs;"
                            + " engine %s, Graal compiler %s%n",
                    loop ? "loop script" : "onInstantiate", micros[runs / 2] / 1000.0, micros[runs * 9 / 10] / 1000.0, runs, warmUp,
                    runtime.engineName(), runtime.compilerEnabled() ? "on" : "off (interpreter only)");
        }
        if (sent.get() != (long) runs + warmUp) {
            throw new IllegalStateException("Sendmsg was called " + sent.get() + " times, expected " + (runs + warmUp) + ".");
        }
    }

    private static void runOnce(ScriptRuntime runtime, CompiledScript script, AtomicLong sent, int i) {
        runtime.run(script, Map.of(
                "s", Proxies.object(Map.of("mMouth", "mouth1", "mUser", i % 2 == 0 ? "Ann" : "Bob")),
                "Sendmsg", Proxies.procedure(arguments -> sent.incrementAndGet())));
    }
}
