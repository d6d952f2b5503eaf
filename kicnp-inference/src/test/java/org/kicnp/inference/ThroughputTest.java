package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.Provenance;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A sanity check, not a timed assertion: stimuli through a three-deep chain plus an equality join, at two sizes, so a
 * quadratic matcher would show in the log (twice the stimuli should take about twice the time, not four times).
 */
class ThroughputTest {
    private static final Logger LOG = LoggerFactory.getLogger(ThroughputTest.class);

    @Test
    void chainOfThree_withJoin_handlesTenThousandStimuliAndEveryOneDerivesItsChain() {
        run(2_500);
        long ms = run(10_000);
        assertThat(ms).isPositive();
    }

    private static long run(int n) {
        Fixture f = ForwardChainingTest.chain3();
        f.cls("Ticket", null);
        f.kb.add(Frame.classFrame("Match").slot(Fixture.inst("mStep", "Step3"))
                .slot(Fixture.inst("mTicket", "Ticket", ".no == mStep.mIn.mIn.mIn.no")).build());
        InferenceEngine e = InferenceEngine.builder(f.kb).options(EngineOptions.defaults().withMaxFirings(1_000_000)).build();
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        long cpuStart = mx.getCurrentThreadCpuTime();
        long start = System.nanoTime();
        List<Change> tickets = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            tickets.add(new Change.Add(Frame.instance("t" + i, "Ticket").provenance(Provenance.RUNTIME)
                    .slot(Fixture.num("no", i)).build()));
        }
        f.kb.apply(tickets);
        for (int i = 0; i < n; i++) {
            f.kb.add(Frame.instance("s" + i, "Stimulus").provenance(Provenance.RUNTIME)
                    .slot(Fixture.num("no", i)).build());
        }
        int fired = e.runToQuiescence();
        long ms = (System.nanoTime() - start) / 1_000_000;
        long cpuMs = (mx.getCurrentThreadCpuTime() - cpuStart) / 1_000_000;
        LOG.info("Throughput: {} stimuli, {} firings, {} ms wall, {} ms CPU ({} firings per CPU second)", n, fired, ms,
                cpuMs, fired * 1000L / Math.max(1, cpuMs));
        assertThat(fired).isEqualTo(4 * n);
        assertThat(f.kb.countInstancesOf("Match")).isEqualTo(n);
        return ms;
    }
}
