package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A node's referrers are a set in insertion order whatever form they are kept in (none, one node, a short array, a
 * {@link NodeSet} past {@value Node#FEW_REFERRERS}): each test goes through the forms and back, against a list.
 */
class NodeReferrersTest {

    @Test
    void add_keepsInsertionOrder_refusesAReferrerTwice_inEveryForm() {
        Node target = node("T");
        List<Node> rs = nodes(Node.FEW_REFERRERS + 5);
        assertThat(target.referrers()).isEmpty();
        for (int i = 0; i < rs.size(); i++) {
            target.addReferrer(rs.get(i));
            target.addReferrer(rs.get(i)); // two slots of one frame naming the same instance
            target.addReferrer(rs.get(i / 2)); // an earlier one again
            assertThat(target.referrers()).as("after %d", i + 1).containsExactlyElementsOf(rs.subList(0, i + 1));
        }
    }

    @Test
    void remove_keepsTheOthersInOrder_downToNone_fromEachForm() {
        for (int size : new int[] {1, 2, 3, Node.FEW_REFERRERS, Node.FEW_REFERRERS + 1, 40}) {
            for (int first = 0; first < size; first++) {
                Node target = node("T");
                List<Node> expected = new ArrayList<>(nodes(size));
                expected.forEach(target::addReferrer);
                // remove from position `first` on, wrapping round, so each position goes first once
                for (int k = 0; k < size; k++) {
                    Node r = expected.get(first % expected.size());
                    target.removeReferrer(r);
                    expected.remove(r);
                    assertThat(target.referrers()).as("size %d, from %d, removed %d", size, first, k + 1)
                            .containsExactlyElementsOf(expected);
                }
                target.removeReferrer(node("absent"));
                assertThat(target.referrers()).isEmpty();
            }
        }
    }

    @Test
    void randomAddsAndRemoves_agreeWithAListKeptAsASet() {
        Random random = new Random(7);
        List<Node> pool = nodes(30);
        Node target = node("T");
        List<Node> expected = new ArrayList<>();
        for (int step = 0; step < 5_000; step++) {
            Node r = pool.get(random.nextInt(random.nextBoolean() ? 4 : pool.size()));
            if (random.nextInt(3) == 0) {
                target.removeReferrer(r);
                expected.remove(r);
            } else {
                target.addReferrer(r);
                if (!expected.contains(r)) {
                    expected.add(r);
                }
            }
            assertThat(target.referrers()).as("step %d", step).containsExactlyElementsOf(expected);
        }
    }

    @Test
    void knowledgeBase_referrers_throughAddsAndRemoves_ofManyInstancesNamingOne() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("Stim").build());
        kb.add(Frame.classFrame("Pair").slot(Frames.instanceSlot("mA", "Stim"))
                .slot(Frames.instanceSlot("mB", "Stim")).build());
        kb.add(Frame.instance("s", "Stim").provenance(Provenance.RUNTIME).build());
        kb.add(Frame.instance("t", "Stim").provenance(Provenance.RUNTIME).build());
        List<String> expected = new ArrayList<>();
        for (int i = 0; i < 12; i++) {
            kb.add(Frame.instance("P" + i, "Pair").provenance(Provenance.RUNTIME)
                    .slot(Slot.builder("mA", DataType.INSTANCE).value(Value.ref("s")).build())
                    .slot(Slot.builder("mB", DataType.INSTANCE).value(Value.ref(i % 2 == 0 ? "s" : "t")).build())
                    .build());
            expected.add("P" + i);
        }
        assertThat(kb.referrers("s")).containsExactlyElementsOf(expected);
        for (int i : new int[] {0, 5, 11, 6, 1, 2, 3}) {
            kb.remove("P" + i);
            expected.remove("P" + i);
            assertThat(kb.referrers("s")).containsExactlyElementsOf(expected);
        }
        assertThat(kb.referrers("t")).containsExactly("P7", "P9");
        for (String p : List.copyOf(expected)) {
            kb.remove(p);
        }
        assertThat(kb.referrers("s")).isEmpty();
        assertThat(kb.referrers("t")).isEmpty();
        kb.remove("s"); // nothing refers to it any more
        assertThat(kb.contains("s")).isFalse();
    }

    private static Node node(String name) {
        return new Node(Frame.classFrame(name).build());
    }

    private static List<Node> nodes(int count) {
        List<Node> out = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            out.add(node("R" + i));
        }
        return out;
    }
}
