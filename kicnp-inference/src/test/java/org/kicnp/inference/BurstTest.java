package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;

/**
 * The engine's hold on the knowledge base across firings ({@link Burst}): it must never outlast a run, a script, or
 * {@value Burst#FIRINGS} firings, since other threads (the gateway's sensor signals, the editor) wait for it.
 */
class BurstTest {
    private final ExecutorService pool = Executors.newCachedThreadPool();

    @AfterEach
    void stopPool() {
        pool.shutdownNow();
    }

    /** Whether another thread can read {@code kb} now (within 2 s). */
    private boolean otherThreadCanRead(KnowledgeBase kb) throws Exception {
        return CompletableFuture.supplyAsync(kb::version, pool).thenApply(v -> true)
                .completeOnTimeout(false, 2, TimeUnit.SECONDS).get();
    }

    @Test
    void aRunOfFirings_leavesTheKnowledgeBaseFreeForOtherThreads() throws Exception {
        Fixture f = new Fixture();
        f.cls("Stimulus", null);
        f.kb.add(Frame.classFrame("Step1").slot(Fixture.inst("mIn", "Stimulus")).build());
        f.kb.add(Frame.classFrame("Step2").slot(Fixture.inst("mIn", "Step1")).build());
        InferenceEngine e = f.engine();
        for (int i = 0; i < 200; i++) {
            f.assertFact("s" + i, "Stimulus");
        }
        assertThat(e.runToQuiescence()).isEqualTo(400);
        assertThat(otherThreadCanRead(f.kb)).isTrue();
        assertThat(CompletableFuture.supplyAsync(() -> f.kb.add(Frame.instance("late", "Stimulus")
                .provenance(Provenance.RUNTIME).build()), pool).get(10, TimeUnit.SECONDS).events()).hasSize(1);
    }

    @Test
    void scriptsRun_withTheKnowledgeBaseFreeForOtherThreads() throws Exception {
        Fixture f = new Fixture();
        f.cls("Stimulus", null);
        f.kb.add(Frame.classFrame("Step1").slot(Fixture.inst("mIn", "Stimulus")).build());
        f.kb.add(Frame.classFrame("Step2").slot(Fixture.inst("mIn", "Step1"))
                .slot(Fixture.str("onInstantiate", "probe")).build());
        List<Boolean> readable = new ArrayList<>();
        f.scripts.define("probe", g -> {
            try {
                readable.add(otherThreadCanRead(f.kb));
            } catch (Exception x) {
                throw new IllegalStateException(x);
            }
            return null;
        });
        InferenceEngine e = f.engine();
        for (int i = 0; i < 3; i++) {
            f.assertFact("s" + i, "Stimulus");
        }
        e.runToQuiescence();
        assertThat(readable).as("one probe per Step2, each while the engine was between plain firings")
                .containsExactly(true, true, true);
    }

    @Test
    void aHold_isGivenBackAfter64Firings() throws Exception {
        KnowledgeBase kb = KnowledgeBase.create();
        Burst burst = new Burst(kb);
        for (int i = 1; i < Burst.FIRINGS; i++) {
            burst.beforeFiring();
            burst.afterFiring();
        }
        assertThat(burst.holding()).isTrue();
        assertThat(CompletableFuture.supplyAsync(kb::version, pool)
                .completeOnTimeout(-1L, 300, TimeUnit.MILLISECONDS).get()).as("held: another thread waits").isEqualTo(-1L);
        burst.beforeFiring();
        burst.afterFiring();
        assertThat(burst.holding()).isFalse();
        assertThat(otherThreadCanRead(kb)).isTrue();
    }
}
