package org.kicnp.script;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;

class ConcurrencyTest {

    @Test
    void run_fromFourThreads_givesEveryRunItsOwnGlobals() throws Exception {
        int threads = 4;
        int runs = 500;
        AtomicInteger calls = new AtomicInteger();
        try (ScriptRuntime runtime = ScriptRuntime.create(ScriptConfig.defaults()
                .withMaxIdleContexts(threads).withTimeLimit(Duration.ofSeconds(10)));
             ExecutorService pool = Executors.newFixedThreadPool(threads)) {
            CompiledScript script = runtime.compile(new ScriptId("Counter", "onInstantiate"),
                    "let sum = 0; for (let i = 0; i < s.n; i++) { sum += i; } Record(s.who); s.who + ':' + sum");
            List<Future<List<Object>>> futures = new ArrayList<>();
            for (int t = 0; t < threads; t++) {
                int thread = t;
                futures.add(pool.submit(() -> {
                    List<Object> results = new ArrayList<>();
                    for (int r = 0; r < runs; r++) {
                        int n = thread * 10 + r % 7;
                        results.add(runtime.run(script, Map.of(
                                "s", Map.of("who", "t" + thread + "r" + r, "n", n),
                                "Record", Proxies.procedure(a -> calls.incrementAndGet()))));
                        assertThat(results.getLast()).isEqualTo("t" + thread + "r" + r + ":" + (long) n * (n - 1) / 2);
                    }
                    return results;
                }));
            }
            for (Future<List<Object>> future : futures) {
                assertThat(future.get()).hasSize(runs);
            }
            assertThat(runtime.contextsCreated()).isLessThanOrEqualTo(threads + 1);
        }
        assertThat(calls).hasValue(threads * runs);
    }
}
