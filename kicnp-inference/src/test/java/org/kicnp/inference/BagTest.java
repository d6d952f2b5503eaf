package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class BagTest {

    /**
     * Random adds, adds-if-absent and removals of a few values: the bag holds what the list the engine used before
     * held (an ArrayList, turned into a LinkedHashSet on growing past eight), in the same order. Neither holds an
     * element twice: each fact's activations, dependents and fired bindings are distinct.
     */
    @Test
    void addsAndRemovals_keepTheElementsOfTheListItReplaces_inOrder() {
        Random random = new Random(5);
        for (int round = 0; round < 500; round++) {
            Object bag = null;
            java.util.Collection<String> reference = null;
            for (int step = 0; step < 60; step++) {
                String x = "v" + random.nextInt(round % 2 == 0 ? 6 : 30);
                switch (random.nextInt(4)) {
                    case 0 -> { // add without a check: the engine's callers add only what is not there
                        if (reference == null || !reference.contains(x)) {
                            bag = Bag.add(bag, x);
                            reference = grown(reference);
                            reference.add(x);
                        }
                    }
                    case 1 -> {
                        bag = Bag.addIfAbsent(bag, x);
                        reference = grown(reference);
                        if (!reference.contains(x)) {
                            reference.add(x);
                        }
                    }
                    default -> {
                        bag = Bag.remove(bag, x);
                        if (reference != null) {
                            reference.remove(x);
                            if (reference.isEmpty()) {
                                reference = null;
                            }
                        }
                    }
                }
                List<String> expected = reference == null ? List.of() : new ArrayList<>(reference);
                assertThat(Bag.<String>toList(bag)).as("round %d step %d", round, step).isEqualTo(expected);
                assertThat(Bag.size(bag)).isEqualTo(expected.size());
                assertThat(bag == null).as("empty is null").isEqualTo(expected.isEmpty());
                for (int v = 0; v < 30; v++) {
                    assertThat(Bag.contains(bag, "v" + v)).isEqualTo(expected.contains("v" + v));
                }
            }
        }
    }

    @Test
    void oneElement_isHeldAsItself_noArray() {
        String only = "Pair-1";
        Object bag = Bag.add(null, only);
        assertThat(bag).isSameAs(only);
        assertThat(Bag.size(bag)).isEqualTo(1);
        assertThat(Bag.contains(bag, "Pair-1")).isTrue();
        assertThat(Bag.contains(bag, "Pair-2")).isFalse();
        assertThat(Bag.remove(bag, "Pair-2")).isSameAs(only);
        assertThat(Bag.<String>toList(bag)).containsExactly("Pair-1");
        assertThat(Bag.remove(bag, "Pair-1")).isNull();
        Object two = Bag.add(bag, "Pair-2");
        assertThat(two).isInstanceOf(Object[].class);
        assertThat(Bag.<String>toList(two)).containsExactly("Pair-1", "Pair-2");
    }

    @Test
    void aShortBag_isOneArray_andPastEightASet() {
        Object bag = null;
        for (int i = 0; i < 8; i++) {
            bag = Bag.add(bag, i);
        }
        assertThat(bag).isInstanceOf(Object[].class);
        bag = Bag.add(bag, 8);
        assertThat(bag).isInstanceOf(LinkedHashSet.class);
        assertThat(Bag.<Integer>toList(bag)).containsExactly(0, 1, 2, 3, 4, 5, 6, 7, 8);
    }

    /** The engine's former per-fact list: an ArrayList, a LinkedHashSet (same order) once it held eight. */
    private static java.util.Collection<String> grown(java.util.Collection<String> c) {
        if (c == null) {
            return new ArrayList<>(2);
        }
        return c.size() == Bag.SMALL && c instanceof ArrayList ? new LinkedHashSet<>(c) : c;
    }
}
