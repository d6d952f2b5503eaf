package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;

class NodeSetTest {

    @Test
    void add_keepsInsertionOrder_andRefusesAMemberTwice() {
        List<Node> nodes = nodes(20);
        NodeSet set = new NodeSet(2);

        for (Node n : nodes) {
            assertThat(set.add(n)).isTrue();
        }
        assertThat(set.add(nodes.get(3))).isFalse();
        assertThat(set.add(nodes.get(15))).isFalse();

        assertThat(set.size()).isEqualTo(20);
        assertThat(set).containsExactlyElementsOf(nodes);
    }

    @Test
    void remove_leavesTheOthersInOrder_throughCompaction() {
        List<Node> nodes = nodes(1_000);
        NodeSet set = new NodeSet(4);
        nodes.forEach(set::add);

        List<Node> kept = new ArrayList<>();
        for (int i = 0; i < nodes.size(); i++) {
            if (i % 3 == 0) {
                kept.add(nodes.get(i));
            } else {
                assertThat(set.remove(nodes.get(i))).isTrue();
            }
        }

        assertThat(set.remove(nodes.get(1))).isFalse();
        assertThat(set).containsExactlyElementsOf(kept);
        assertThat(set.size()).isEqualTo(kept.size());
        assertThat(set.contains(nodes.get(1))).isFalse();
        assertThat(set.contains(nodes.get(999))).isTrue();
    }

    @Test
    void addAndRemove_inRandomOrder_behaveLikeALinkedHashSet() {
        List<Node> nodes = nodes(500);
        Random random = new Random(7);
        NodeSet set = new NodeSet(2);
        Set<Node> reference = new LinkedHashSet<>();

        for (int step = 0; step < 20_000; step++) {
            Node n = nodes.get(random.nextInt(nodes.size()));
            if (random.nextInt(3) == 0) {
                assertThat(set.remove(n)).isEqualTo(reference.remove(n));
            } else {
                assertThat(set.add(n)).isEqualTo(reference.add(n));
            }
            assertThat(set.size()).isEqualTo(reference.size());
        }

        assertThat(set).containsExactlyElementsOf(reference);
        for (Node n : nodes) {
            assertThat(set.contains(n)).isEqualTo(reference.contains(n));
        }
    }

    @Test
    void removeAll_ofEveryMember_emptiesTheSet_whichThenTakesMembersAgain() {
        List<Node> nodes = nodes(40);
        NodeSet set = new NodeSet(2);
        NodeSet same = new NodeSet(2);
        nodes.forEach(set::add);
        nodes.forEach(same::add);

        set.removeAll(same);

        assertThat(set.isEmpty()).isTrue();
        assertThat(set.iterator().hasNext()).isFalse();
        set.add(nodes.get(7));
        assertThat(set).containsExactly(nodes.get(7));
    }

    @Test
    void addNew_ofManyNodes_thenMembershipQuestions_areAnsweredAsWithAdd() {
        List<Node> nodes = nodes(3_000);
        NodeSet set = new NodeSet(2);
        nodes.subList(0, 2_000).forEach(set::addNew);

        assertThat(set.contains(nodes.get(1_999))).isTrue();
        assertThat(set.contains(nodes.get(2_000))).isFalse();
        assertThat(set.add(nodes.get(5))).isFalse();
        nodes.subList(2_000, 3_000).forEach(set::addNew);
        for (int i = 0; i < 3_000; i += 2) {
            assertThat(set.remove(nodes.get(i))).isTrue();
        }

        List<Node> odd = new ArrayList<>();
        for (int i = 1; i < 3_000; i += 2) {
            odd.add(nodes.get(i));
        }
        assertThat(set).containsExactlyElementsOf(odd);
        assertThat(set.size()).isEqualTo(1_500);
        assertThat(set.contains(nodes.get(2_999))).isTrue();
        assertThat(set.contains(nodes.get(2_998))).isFalse();
    }

    private static List<Node> nodes(int count) {
        List<Node> out = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            out.add(new Node(Frame.classFrame("N" + i).build()));
        }
        return out;
    }
}
