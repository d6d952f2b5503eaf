package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Condition;

/**
 * The agenda's queue gives activations in exactly the order a sorted set in {@link Agenda#ORDER} would, whether they
 * arrive in recency order (the lanes' groups) or out of it (the lanes' heaps), across ranks, with withdrawals and
 * clears in between.
 */
class ActivationQueueTest {

    private static Rule rule(String frame, int priority, int depth) {
        SlotPattern p = new SlotPattern(0, "m", "C", Condition.ANY, "COND_ANY", true, true, false, true, Set.of(),
                Optional.empty());
        return Rule.of(frame, priority, depth, 0, List.of(p), List.of(), Optional.empty());
    }

    private final List<Rule> rules = List.of(rule("R0", 0, 1), rule("R1", 3, 1), rule("R2", 3, 2), rule("R3", -1, 4),
            rule("R4", 0, 1), rule("R5", 7, 0));

    @Test
    void mostlyInOrderArrivals_withWithdrawalsAndPolls_matchASortedSet() {
        for (long seed = 1; seed <= 20; seed++) {
            replay(new Random(seed), 20_000, 0.1);
        }
    }

    @Test
    void arrivalsInAnyOrder_matchASortedSet() {
        replay(new Random(5), 20_000, 1.0);
    }

    @Test
    void arrivalsAlwaysInOrder_neverUseTheHeap_andMatchASortedSet() {
        replay(new Random(9), 20_000, 0.0);
    }

    /**
     * @param outOfOrder the share of adds given an older recency than the newest stamp (a binding matched again)
     */
    private void replay(Random random, int steps, double outOfOrder) {
        ActivationQueue queue = new ActivationQueue();
        TreeSet<Activation> reference = new TreeSet<>(Agenda.ORDER);
        List<Activation> queued = new ArrayList<>();
        List<Activation> gone = new ArrayList<>();
        long seq = 0;
        long stamp = 0;

        for (int step = 0; step < steps; step++) {
            int op = random.nextInt(10);
            if (op < 5) {
                if (random.nextInt(3) == 0) {
                    stamp++; // a new fact: its bindings carry its stamp
                }
                long recency = random.nextDouble() < outOfOrder ? random.nextLong(stamp + 1) : stamp;
                Activation a = new Activation(rules.get(random.nextInt(rules.size())), new String[] {"f" + step},
                        new FactView.Fact[0], recency, ++seq);
                queue.add(a);
                reference.add(a);
                queued.add(a);
            } else if (op < 8) {
                Activation first = queue.poll();
                assertThat(first).isSameAs(reference.pollFirst());
                if (first != null) {
                    queued.remove(first);
                    gone.add(first);
                }
            } else if (op < 9 || step % 997 != 0) {
                if (!queued.isEmpty()) {
                    Activation out = queued.remove(random.nextInt(queued.size()));
                    assertThat(queue.remove(out)).isTrue();
                    assertThat(queue.remove(out)).isFalse();
                    reference.remove(out);
                    gone.add(out);
                }
            } else {
                queue.clear();
                reference.clear();
                gone.addAll(queued);
                queued.clear();
            }
            assertThat(queue.size()).isEqualTo(reference.size());
            if (step % 1000 == 0) {
                assertThat(queue.inOrder()).containsExactlyElementsOf(reference);
                assertThat(queue.snapshot()).containsExactlyInAnyOrderElementsOf(reference);
            }
        }
        for (Activation a : gone.subList(Math.max(0, gone.size() - 100), gone.size())) {
            assertThat(queue.remove(a)).isFalse();
        }

        assertThat(queue.inOrder()).containsExactlyElementsOf(reference);
        while (!reference.isEmpty()) {
            assertThat(queue.poll()).isSameAs(reference.pollFirst());
        }
        assertThat(queue.poll()).isNull();
        assertThat(queue.size()).isZero();
    }
}
