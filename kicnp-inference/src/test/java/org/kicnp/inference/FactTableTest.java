package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

class FactTableTest {

    /** Names sharing a number, numbers far beyond the array, names without one: the table is a map all the same. */
    @Test
    void touchGetAndRemove_inRandomOrder_behaveLikeAMap() {
        Random random = new Random(11);
        FactTable table = new FactTable();
        Map<String, FactView.Fact> reference = new HashMap<>();
        List<String> names = new ArrayList<>();
        for (int i = 0; i < 2_000; i++) {
            names.add("Pair-" + i);
            names.add("Alert-" + i);
            names.add("s" + i);
            names.add("x-0" + i);
            names.add("far-" + (5_000_000 + i * 7));
        }
        names.addAll(List.of("-3", "y-", "z-1234567890", "a-b-7"));

        for (int step = 0; step < 100_000; step++) {
            String name = names.get(random.nextInt(names.size()));
            switch (random.nextInt(3)) {
                case 0 -> assertThat(table.remove(name)).isSameAs(reference.remove(name));
                case 1 -> assertThat(table.get(name)).isSameAs(reference.get(name));
                default -> {
                    FactView.Fact f = table.touch(name);
                    assertThat(f.name).isEqualTo(name);
                    assertThat(reference.computeIfAbsent(name, k -> f)).isSameAs(f);
                }
            }
            assertThat(table.size()).isEqualTo(reference.size());
        }

        for (String name : names) {
            assertThat(table.get(name)).isSameAs(reference.get(name));
        }
        List<FactView.Fact> all = new ArrayList<>();
        table.forEach(all::add);
        assertThat(all).containsExactlyInAnyOrderElementsOf(reference.values());
    }

    @Test
    void aNameWhoseNumberIsTaken_isFoundInTheTable_alsoAfterTheNumberIsFreed() {
        FactTable table = new FactTable();
        FactView.Fact pair = table.touch("Pair-5");
        FactView.Fact alert = table.touch("Alert-5");

        assertThat(table.remove("Pair-5")).isSameAs(pair);
        assertThat(table.get("Pair-5")).isNull();
        assertThat(table.get("Alert-5")).isSameAs(alert);
        assertThat(table.touch("Alert-5")).isSameAs(alert);
        assertThat(table.remove("Alert-5")).isSameAs(alert);
        assertThat(table.size()).isZero();
        FactView.Fact again = table.touch("Alert-5");
        assertThat(again).isNotSameAs(alert);
        assertThat(table.get("Alert-5")).isSameAs(again);
    }

    /** A long run that retracts what it derived: the numbers grow, the array does not. */
    @Test
    void numbersGrowingWhileFewFactsLive_keepTheArraySmall() {
        FactTable table = new FactTable();
        for (int i = 1; i <= 1_000_000; i++) {
            table.touch("Pair-" + i);
            if (i > 100) {
                assertThat(table.remove("Pair-" + (i - 100))).isNotNull();
            }
        }
        assertThat(table.size()).isEqualTo(100);
        assertThat(table.capacity()).isLessThanOrEqualTo(1024);
        assertThat(table.get("Pair-999999")).isNotNull();
        assertThat(table.get("Pair-5")).isNull();
    }

    @Test
    void growing_keepsEveryFact_inTheArrayAndInTheTable() {
        FactTable table = new FactTable();
        Map<String, FactView.Fact> reference = new HashMap<>();
        for (int i = 0; i < 20_000; i++) {
            for (String name : List.of("Pair-" + i, "Alert-" + i, "s" + i)) {
                reference.put(name, table.touch(name));
            }
        }
        assertThat(table.capacity()).isGreaterThan(1024);
        for (Map.Entry<String, FactView.Fact> e : reference.entrySet()) {
            assertThat(table.get(e.getKey())).isSameAs(e.getValue());
            assertThat(table.touch(e.getKey())).isSameAs(e.getValue());
        }
        assertThat(table.size()).isEqualTo(reference.size());
    }

    /** Numbers given out one after the other fill the array to its last place before it doubles. */
    @Test
    void consecutiveNumbers_fillTheArray_beforeItGrows() {
        FactTable table = new FactTable();
        int first = table.capacity();
        for (int i = 0; i < first; i++) {
            table.touch("Pair-" + i);
        }
        assertThat(table.capacity()).isEqualTo(first);
        FactView.Fact last = table.touch("Pair-" + first); // its index holds Pair-0
        assertThat(table.capacity()).isEqualTo(2 * first);
        assertThat(table.get("Pair-" + first)).isSameAs(last);
        for (int i = 0; i <= first; i++) {
            assertThat(table.get("Pair-" + i)).isNotNull().extracting(f -> f.name).isEqualTo("Pair-" + i);
        }
        assertThat(table.size()).isEqualTo(first + 1);
    }

    /** Room made for a batch: the array and the table grow once, and the batch goes in without growing them. */
    @Test
    void ensureRoom_growsOnceForTheBatch_keepingEveryFact() {
        FactTable table = new FactTable();
        FactView.Fact held = table.touch("Pair-1");
        FactView.Fact plain = table.touch("s1");
        table.ensureRoom(20_000, 20_000);
        int capacity = table.capacity();
        assertThat(capacity).isGreaterThanOrEqualTo(2 * 20_001);
        for (int i = 2; i < 20_002; i++) {
            table.touch("s" + i);
            table.touch("Pair-" + i);
        }
        assertThat(table.capacity()).isEqualTo(capacity);
        assertThat(table.size()).isEqualTo(40_002);
        assertThat(table.get("Pair-1")).isSameAs(held);
        assertThat(table.get("s1")).isSameAs(plain);
        assertThat(table.get("Pair-20001")).isNotNull();
    }
}
