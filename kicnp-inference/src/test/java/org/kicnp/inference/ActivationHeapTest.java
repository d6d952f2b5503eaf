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

/** The agenda's heap gives activations in exactly the order a sorted set in {@link Agenda#ORDER} would. */
class ActivationHeapTest {

    private static Rule rule(String frame, int priority, int depth) {
        SlotPattern p = new SlotPattern(0, "m", "C", Condition.ANY, "COND_ANY", true, true, false, true, Set.of(),
                Optional.empty());
        return Rule.of(frame, priority, depth, 0, List.of(p), List.of(), Optional.empty());
    }

    @Test
    void addPollAndRemove_inRandomOrder_matchASortedSet() {
        List<Rule> rules = List.of(rule("R0", 0, 1), rule("R1", 3, 1), rule("R2", 3, 2), rule("R3", -1, 4));
        Random random = new Random(11);
        ActivationHeap heap = new ActivationHeap();
        TreeSet<Activation> reference = new TreeSet<>(Agenda.ORDER);
        List<Activation> queued = new ArrayList<>();
        long seq = 0;

        for (int step = 0; step < 20_000; step++) {
            int op = random.nextInt(5);
            if (op < 3) {
                Activation a = new Activation(rules.get(random.nextInt(rules.size())), new String[] {"f" + step},
                        new FactView.Fact[0], random.nextInt(50), ++seq);
                heap.add(a);
                reference.add(a);
                queued.add(a);
            } else if (op == 3) {
                Activation first = heap.poll();
                assertThat(first).isSameAs(reference.pollFirst());
                queued.remove(first);
            } else if (!queued.isEmpty()) {
                Activation gone = queued.remove(random.nextInt(queued.size()));
                assertThat(heap.remove(gone)).isTrue();
                assertThat(heap.remove(gone)).isFalse();
                reference.remove(gone);
            }
            assertThat(heap.size()).isEqualTo(reference.size());
        }

        assertThat(heap.inOrder()).containsExactlyElementsOf(reference);
        while (!reference.isEmpty()) {
            assertThat(heap.poll()).isSameAs(reference.pollFirst());
        }
        assertThat(heap.poll()).isNull();
    }
}
