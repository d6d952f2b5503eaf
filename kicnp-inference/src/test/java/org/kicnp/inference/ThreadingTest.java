package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;
import org.kicnp.core.Provenance;

class ThreadingTest {

    @Test
    void stimuliFromOtherThreads_areQueuedAndProcessedOnTheEngineThread() throws Exception {
        Fixture f = ForwardChainingTest.chain3();
        InferenceEngine e = f.engine();
        List<Thread> engineThreads = new java.util.concurrent.CopyOnWriteArrayList<>();
        e.addTraceListener(t -> {
            if (t instanceof TraceEvent.Fired) {
                engineThreads.add(Thread.currentThread());
            }
        });
        CountDownLatch go = new CountDownLatch(1);
        List<Thread> agents = new ArrayList<>();
        for (int a = 0; a < 4; a++) {
            int id = a;
            agents.add(Thread.ofPlatform().start(() -> {
                try {
                    go.await();
                } catch (InterruptedException ex) {
                    Thread.currentThread().interrupt();
                }
                for (int i = 0; i < 50; i++) {
                    f.kb.add(Frame.instance("s" + id + "_" + i, "Stimulus").provenance(Provenance.RUNTIME).build());
                }
            }));
        }
        go.countDown();
        for (Thread t : agents) {
            t.join();
        }
        assertThat(f.instancesOf("Step1")).isEmpty();
        assertThat(e.runToQuiescence()).isEqualTo(600);
        assertThat(f.instancesOf("Step3")).hasSize(200);
        assertThat(engineThreads).containsOnly(Thread.currentThread());
    }

    @Test
    void runOn_singleThreadExecutor_reachesQuiescenceByItselfOnThatThread() throws Exception {
        Fixture f = ForwardChainingTest.chain3();
        java.util.concurrent.ExecutorService owner = java.util.concurrent.Executors.newSingleThreadExecutor(
                r -> new Thread(r, "engine-owner"));
        try {
            InferenceEngine e = InferenceEngine.builder(f.kb).runOn(owner).build();
            List<String> threads = new java.util.concurrent.CopyOnWriteArrayList<>();
            e.addTraceListener(t -> threads.add(Thread.currentThread().getName()));
            f.assertFact("s1", "Stimulus");
            long deadline = System.nanoTime() + 10_000_000_000L;
            while (f.kb.countInstancesOf("Step3") == 0 && System.nanoTime() < deadline) {
                Thread.sleep(5);
            }
            assertThat(f.instancesOf("Step3")).hasSize(1);
            assertThat(threads).isNotEmpty().containsOnly("engine-owner");
        } finally {
            owner.shutdownNow();
        }
    }

    @Test
    void runOn_anExecutorThatRefusesARun_failsNoCallerAndRunsWhenItAcceptsAgain() throws Exception {
        Fixture f = ForwardChainingTest.chain3();
        java.util.concurrent.atomic.AtomicBoolean refusing = new java.util.concurrent.atomic.AtomicBoolean(true);
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newSingleThreadExecutor();
        java.util.concurrent.Executor owner = task -> { // a bounded pool that is full, then has room
            if (refusing.get()) {
                throw new java.util.concurrent.RejectedExecutionException("the pool is full");
            }
            pool.execute(task);
        };
        try {
            InferenceEngine e = InferenceEngine.builder(f.kb).runOn(owner).build();
            f.assertFact("s1", "Stimulus"); // queued; the executor refuses the run it schedules
            assertThat(f.instancesOf("Step1")).isEmpty();
            refusing.set(false);
            e.tick(); // the next arrival schedules the run the executor refused
            await(() -> f.kb.countInstancesOf("Step3") == 1);
            assertThat(f.instancesOf("Step3")).hasSize(1);
        } finally {
            pool.shutdownNow();
        }
    }

    @Test
    void tick_onSelfRunningEngine_timesOutOverdueActions() throws Exception {
        Fixture f = new Fixture();
        f.cls("Go", null);
        f.kb.add(Frame.classFrame("A").slot(Fixture.inst("mGo", "Go")).slot(Fixture.str("onInstantiate", "cmd"))
                .build());
        f.scripts.define("cmd", g -> Fixture.call(g, "command", "PINO", "walk"));
        java.util.concurrent.atomic.AtomicLong now = new java.util.concurrent.atomic.AtomicLong(1_000);
        java.util.concurrent.ExecutorService owner = java.util.concurrent.Executors.newSingleThreadExecutor();
        try {
            InferenceEngine e = InferenceEngine.builder(f.kb).scripts(f.scripts).clock(now::get).runOn(owner)
                    .options(EngineOptions.defaults().withActionTimeout(java.time.Duration.ofSeconds(1))).build();
            f.assertFact("go", "Go");
            await(() -> e.actions().size() == 1);
            String id = e.actions().getFirst().id();
            now.addAndGet(5_000);
            assertThat(e.actionStatus(id)).contains(Action.Status.SENT);
            e.tick();
            await(() -> e.actionStatus(id).equals(java.util.Optional.of(Action.Status.TIMED_OUT)));
            assertThat(e.actionStatus(id)).contains(Action.Status.TIMED_OUT);
        } finally {
            owner.shutdownNow();
        }
    }

    private static void await(java.util.function.BooleanSupplier condition) throws InterruptedException {
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (!condition.getAsBoolean() && System.nanoTime() < deadline) {
            Thread.sleep(5);
        }
    }
}
