package org.kicnp.script;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

class LimitsTest {
    private static final ScriptId LOOP = new ScriptId("Spinner", "onInstantiate");

    @Test
    void run_whenScriptLoopsForever_isStoppedNearTheTimeLimitAndRuntimeStillWorks() {
        try (ScriptRuntime runtime = ScriptRuntime.create(ScriptConfig.defaults()
                .withTimeLimit(Duration.ofMillis(200)).withStatementLimit(Long.MAX_VALUE))) {
            CompiledScript loop = runtime.compile(LOOP, "while (true) {}");
            long start = System.nanoTime();

            assertThatThrownBy(() -> runtime.run(loop, Map.of()))
                    .isInstanceOfSatisfying(ScriptTimeoutException.class,
                            e -> assertThat(e.limit()).isEqualTo(ScriptTimeoutException.Limit.TIME))
                    .hasMessage("Script in slot 'onInstantiate' of frame 'Spinner' was stopped: "
                            + "it exceeded its time limit of 200 ms.");
            long millis = (System.nanoTime() - start) / 1_000_000;

            assertThat(millis).isBetween(150L, 2_000L);
            assertThat(runtime.run(runtime.compile(LOOP, "'still ' + 'working'"), Map.of())).isEqualTo("still working");
            assertThatThrownBy(() -> runtime.run(loop, Map.of())).isInstanceOf(ScriptTimeoutException.class);
            assertThat(runtime.run(runtime.compile(LOOP, "6 * 7"), Map.of())).isEqualTo(42L);
        }
    }

    @Test
    void run_whenStatementLimitExceeded_isStoppedAndRuntimeStillWorks() {
        try (ScriptRuntime runtime = ScriptRuntime.create(ScriptConfig.defaults()
                .withTimeLimit(Duration.ofSeconds(30)).withStatementLimit(1_000))) {
            CompiledScript loop = runtime.compile(LOOP, "for (let i = 0; ; i++) { i = i + 1; }");
            CompiledScript fine = runtime.compile(LOOP, "let t = 0; for (let i = 0; i < 100; i++) { t += i; } t");

            assertThatThrownBy(() -> runtime.run(loop, Map.of()))
                    .isInstanceOfSatisfying(ScriptTimeoutException.class,
                            e -> assertThat(e.limit()).isEqualTo(ScriptTimeoutException.Limit.STATEMENTS))
                    .hasMessage("Script in slot 'onInstantiate' of frame 'Spinner' was stopped: "
                            + "it exceeded its statement limit of 1000 statements.");
            for (int i = 0; i < 20; i++) {
                assertThat(runtime.run(fine, Map.of())).isEqualTo(4950L);
            }
        }
    }

    @Test
    void run_whenHostFunctionBlocksPastTheTimeLimit_interruptsItAndStopsTheScript() {
        try (ScriptRuntime runtime = ScriptRuntime.create(ScriptConfig.defaults().withTimeLimit(Duration.ofMillis(200)))) {
            CompiledScript script = runtime.compile(LOOP, "Slow(); 'finished'");
            long start = System.nanoTime();

            assertThatThrownBy(() -> runtime.run(script, Map.of("Slow", Proxies.procedure(args -> sleep(5_000)))))
                    .isInstanceOf(ScriptTimeoutException.class);

            assertThat((System.nanoTime() - start) / 1_000_000).isBetween(150L, 2_000L);
            assertThat(Thread.currentThread().isInterrupted()).as("the cancellation interrupt is cleared").isFalse();
            assertThat(runtime.run(runtime.compile(LOOP, "'fine'"), Map.of())).isEqualTo("fine");
        }
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Test
    void run_whenOneThreadLoopsForever_otherThreadsKeepRunning() throws Exception {
        try (ScriptRuntime runtime = ScriptRuntime.create(ScriptConfig.defaults()
                .withTimeLimit(Duration.ofMillis(500)).withStatementLimit(Long.MAX_VALUE))) {
            CompiledScript loop = runtime.compile(LOOP, "while (true) {}");
            CompiledScript quick = runtime.compile(LOOP, "s.a + s.b");
            CompletableFuture<Throwable> spinner = CompletableFuture.supplyAsync(() -> {
                try {
                    runtime.run(loop, Map.of());
                    return null;
                } catch (ScriptTimeoutException e) {
                    return e;
                }
            });

            int runs = 0;
            while (!spinner.isDone()) {
                assertThat(runtime.run(quick, Map.of("s", Map.of("a", runs, "b", 1)))).isEqualTo(runs + 1L);
                runs++;
            }

            assertThat(spinner.get(5, TimeUnit.SECONDS)).isInstanceOf(ScriptTimeoutException.class);
            assertThat(runs).isGreaterThan(10);
        }
    }
}
