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
}
