package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

class NodeIndexTest {

    private static Node node(String name) {
        return new Node(Frame.classFrame(name).build());
    }

    /** Gets, puts (new names and names held), removals: the index answers and iterates as a linked hash map. */
    @Test
    void putGetRemove_inRandomOrder_behaveLikeALinkedHashMap_orderIncluded() {
        Random random = new Random(5);
        NodeIndex index = new NodeIndex();
        Map<String, Node> reference = new LinkedHashMap<>();
        List<String> names = new ArrayList<>();
        for (int i = 0; i < 1_500; i++) {
            names.add("Pair-" + i);
            names.add("Alert-" + i); // the same numbers as the pairs'
            names.add("s" + i);
            names.add("x-0" + i);
            names.add("far-" + (5_000_000 + i * 1_024));
        }
        names.addAll(List.of("f5a5a608", "_-3", "y-", "z-1234567890")); // hash 0; odd numbers and none

        for (int step = 0; step < 150_000; step++) {
            String name = names.get(random.nextInt(names.size()));
            switch (random.nextInt(4)) {
                case 0 -> assertThat(index.remove(name)).isSameAs(reference.remove(name));
                case 1 -> {
                    assertThat(index.get(name)).isSameAs(reference.get(name));
                    assertThat(index.containsKey(name)).isEqualTo(reference.containsKey(name));
                }
                default -> {
                    Node n = node(name);
                    index.put(name, n);
                    reference.put(name, n);
                }
            }
            assertThat(index.size()).isEqualTo(reference.size());
            if (step % 1_000 == 0) {
                assertThat(new ArrayList<>(index.values())).containsExactlyElementsOf(reference.values());
            }
        }
        assertThat(new ArrayList<>(index.values())).containsExactlyElementsOf(reference.values());
        for (String name : names) {
            assertThat(index.get(name)).isSameAs(reference.get(name));
        }
    }

    @Test
    void grow_thenRemoveEverything_leavesAnEmptyIndexThatTakesNamesAgain() {
        NodeIndex index = new NodeIndex();
        for (int i = 0; i < 100_000; i++) {
            index.put("Triple-" + i, node("Triple-" + i));
        }
        assertThat(index.size()).isEqualTo(100_000);
        assertThat(index.get("Triple-99999").name()).isEqualTo("Triple-99999");
        for (int i = 0; i < 100_000; i += 2) {
            assertThat(index.remove("Triple-" + i)).isNotNull();
        }
        assertThat(index.values()).hasSize(50_000).first().extracting(Node::name).isEqualTo("Triple-1");
        for (int i = 1; i < 100_000; i += 2) {
            assertThat(index.remove("Triple-" + i)).isNotNull();
        }
        assertThat(index.size()).isZero();
        assertThat(index.values()).isEmpty();
        assertThat(index.get("Triple-5")).isNull();
        index.put("Triple-5", node("Triple-5"));
        assertThat(index.values()).extracting(Node::name).containsExactly("Triple-5");
    }

    /** A long run that retracts what it derived: the numbers grow, the array does not. */
    @Test
    void numbersGrowingWhileFewNodesLive_keepTheArraySmall() {
        NodeIndex index = new NodeIndex();
        for (int i = 1; i <= 1_000_000; i++) {
            index.put("Pair-" + i, node("Pair-" + i));
            if (i > 100) {
                assertThat(index.remove("Pair-" + (i - 100))).isNotNull();
            }
        }
        assertThat(index.size()).isEqualTo(100);
        assertThat(index.numberedCapacity()).isLessThanOrEqualTo(1024);
        assertThat(index.values()).extracting(Node::name).first().isEqualTo("Pair-999901");
        assertThat(index.get("Pair-5")).isNull();
    }

    /** Numbers given out one after the other fill the array to its last place before it doubles. */
    @Test
    void consecutiveNumbers_fillTheArray_beforeItGrows() {
        NodeIndex index = new NodeIndex();
        int first = index.numberedCapacity();
        for (int i = 0; i < first; i++) {
            index.put("Pair-" + i, node("Pair-" + i));
        }
        assertThat(index.numberedCapacity()).isEqualTo(first);
        index.put("Pair-" + first, node("Pair-" + first)); // its index holds Pair-0
        assertThat(index.numberedCapacity()).isEqualTo(2 * first);
        for (int i = 0; i <= first; i++) {
            assertThat(index.get("Pair-" + i)).extracting(Node::name).isEqualTo("Pair-" + i);
        }
        assertThat(index.values()).extracting(Node::name).first().isEqualTo("Pair-0");
        assertThat(index.size()).isEqualTo(first + 1);
    }

    /** Room made for a batch: each part grows once, and the batch's names, numbered or not, go in without growth. */
    @Test
    void ensureRoom_growsOnceForTheBatch_keepingOrderAndNodes() {
        NodeIndex index = new NodeIndex();
        index.put("Thing", node("Thing"));
        index.put("Pair-1", node("Pair-1"));
        index.ensureRoom(20_000, 20_000);
        int capacity = index.numberedCapacity();
        int tableCapacity = index.tableCapacity();
        assertThat(capacity).isGreaterThanOrEqualTo(2 * 20_001);
        assertThat(tableCapacity).isGreaterThanOrEqualTo(2 * 20_001);
        for (int i = 2; i < 20_002; i++) {
            index.put("s" + i, node("s" + i));
            index.put("Pair-" + i, node("Pair-" + i));
        }
        assertThat(index.numberedCapacity()).isEqualTo(capacity);
        assertThat(index.tableCapacity()).isEqualTo(tableCapacity);
        assertThat(index.size()).isEqualTo(40_002);
        assertThat(index.values()).extracting(Node::name).startsWith("Thing", "Pair-1", "s2", "Pair-2");
        assertThat(index.get("Pair-20001")).extracting(Node::name).isEqualTo("Pair-20001");
        assertThat(index.get("s20001")).extracting(Node::name).isEqualTo("s20001");
        index.ensureRoom(0, 0);
        assertThat(index.numberedCapacity()).isEqualTo(capacity);
    }
}
