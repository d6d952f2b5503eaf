package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

class NameTableTest {

    @Test
    void numberOf_readsOnlyASuffixOfOneToNineDigitsAfterADash() {
        assertThat(NameTable.numberOf("Pair-17")).isEqualTo(17);
        assertThat(NameTable.numberOf("a-b-0")).isZero();
        assertThat(NameTable.numberOf("x-05")).isEqualTo(5);
        assertThat(NameTable.numberOf("x-999999999")).isEqualTo(999_999_999);
        assertThat(NameTable.numberOf("x-2147483647")).isEqualTo(-1);
        assertThat(NameTable.numberOf("x-1000000000")).isEqualTo(-1);
        assertThat(NameTable.numberOf("s17")).isEqualTo(-1);
        assertThat(NameTable.numberOf("-17")).isEqualTo(-1);
        assertThat(NameTable.numberOf("Pair-")).isEqualTo(-1);
        assertThat(NameTable.numberOf("Pair-1a")).isEqualTo(-1);
        assertThat(NameTable.numberOf("")).isEqualTo(-1);
    }

    @Test
    void numberOf_aFrame_isTheNumberOfItsName_workedOutOnceAndKept() {
        for (String name : List.of("Pair-17", "a-b-0", "x-05", "x-999999999", "x-1000000000", "s17", "Pair-1a")) {
            Frame f = Frame.instance(name, "Thing").build();
            assertThat(NameTable.numberOf(f)).as(name).isEqualTo(NameTable.numberOf(name));
            assertThat(NameTable.numberOf(f)).as(name + ", asked again").isEqualTo(NameTable.numberOf(name));
        }
    }

    @Test
    void put_replacesAndAnswersTheOldValue_andForEachKeySeesEveryKey() {
        NameTable<String> table = new NameTable<>();
        for (int i = 0; i < 100; i++) {
            assertThat(table.put("k" + i, "v" + i)).isNull();
        }

        assertThat(table.put("k7", "seven")).isEqualTo("v7");
        assertThat(table.get("k7")).isEqualTo("seven");
        assertThat(table.size()).isEqualTo(100);
        java.util.Set<String> keys = new java.util.HashSet<>();
        table.forEachKey(keys::add);
        assertThat(keys).hasSize(100).contains("k0", "k7", "k99");
    }

    @Test
    void putGetAndRemove_inRandomOrder_behaveLikeAHashMap() {
        putGetAndRemove_inRandomOrder_behaveLikeAHashMap(new NameTable<>());
    }

    @Test
    void putGetAndRemove_inRandomOrder_behaveLikeAHashMap_presizedSmallOrLarge() {
        putGetAndRemove_inRandomOrder_behaveLikeAHashMap(new NameTable<>(0));
        putGetAndRemove_inRandomOrder_behaveLikeAHashMap(new NameTable<>(5_000));
    }

    @Test
    void presizing_refusesANegativeOrHugeSize() {
        assertThatThrownBy(() -> new NameTable<>(-1)).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("A name table holds 0 to 2^29 names, not -1.");
        assertThatThrownBy(() -> new NameTable<>((1 << 29) + 1)).isInstanceOf(IllegalArgumentException.class);
    }

    /** Room made for a batch: the table grows once, keeps what it held, and the batch goes in without growing it. */
    @Test
    void ensureCapacity_growsOnceForTheBatch_keepingEveryName() {
        NameTable<String> table = new NameTable<>();
        for (int i = 0; i < 10; i++) {
            table.put("held" + i, "h" + i);
        }
        table.ensureCapacity(table.size() + 5_000);
        int capacity = table.capacity();
        assertThat(capacity).isGreaterThanOrEqualTo(2 * 5_010);
        for (int i = 0; i < 10; i++) {
            assertThat(table.get("held" + i)).isEqualTo("h" + i);
        }
        for (int i = 0; i < 5_000; i++) {
            table.put("s" + i, "v" + i);
        }
        assertThat(table.capacity()).isEqualTo(capacity);
        assertThat(table.size()).isEqualTo(5_010);
        assertThat(table.get("s4999")).isEqualTo("v4999");
        assertThat(table.get("held3")).isEqualTo("h3");

        table.ensureCapacity(10); // never shrinks
        assertThat(table.capacity()).isEqualTo(capacity);
        assertThatThrownBy(() -> table.ensureCapacity(-1)).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("A name table holds 0 to 2^29 names, not -1.");
        assertThat(table.size()).isEqualTo(5_010);
    }

    private static void putGetAndRemove_inRandomOrder_behaveLikeAHashMap(NameTable<String> table) {
        Random random = new Random(3);
        Map<String, String> reference = new HashMap<>();
        List<String> names = new ArrayList<>();
        for (int i = 0; i < 3_000; i++) {
            names.add((i % 3 == 0 ? "Pair-" : i % 3 == 1 ? "s" : "Alert-") + i);
        }

        for (int step = 0; step < 60_000; step++) {
            String name = names.get(random.nextInt(names.size()));
            switch (random.nextInt(3)) {
                case 0 -> assertThat(table.remove(name)).isEqualTo(reference.remove(name));
                case 1 -> assertThat(table.get(name)).isEqualTo(reference.get(name));
                default -> {
                    String v = "v" + step;
                    String expected = reference.computeIfAbsent(name, k -> v);
                    assertThat(table.computeIfAbsent(name, k -> v)).isEqualTo(expected);
                }
            }
            assertThat(table.size()).isEqualTo(reference.size());
        }

        for (String name : names) {
            assertThat(table.get(name)).isEqualTo(reference.get(name));
        }
        List<String> values = new ArrayList<>();
        table.forEach(values::add);
        assertThat(values).containsExactlyInAnyOrderElementsOf(reference.values());
    }

    @Test
    void grow_thenRemoveEverything_leavesAnEmptyTableThatTakesNamesAgain() {
        NameTable<Integer> table = new NameTable<>();
        for (int i = 0; i < 100_000; i++) {
            table.computeIfAbsent("Triple-" + i, k -> k.length());
        }
        assertThat(table.size()).isEqualTo(100_000);
        assertThat(table.get("Triple-99999")).isEqualTo(12);
        for (int i = 0; i < 100_000; i++) {
            assertThat(table.remove("Triple-" + i)).isNotNull();
        }
        assertThat(table.size()).isZero();
        assertThat(table.iterator().hasNext()).isFalse();
        assertThat(table.get("Triple-5")).isNull();
        assertThat(table.computeIfAbsent("Triple-5", k -> 1)).isEqualTo(1);
    }

    @Test
    void aNameWhoseHashIsZero_isKeptApartFromEmptySlotsAndFromANameOfHashOne() {
        // "" and "f5a5a608" hash to 0, which the table stores as 1; "\u0001" hashes to 1.
        assertThat("f5a5a608".hashCode()).isZero();
        assertThat("\u0001".hashCode()).isEqualTo(1);
        NameTable<String> table = new NameTable<>();
        table.computeIfAbsent("f5a5a608", k -> "zero");
        table.computeIfAbsent("\u0001", k -> "one");
        table.computeIfAbsent("", k -> "empty");

        assertThat(table.get("f5a5a608")).isEqualTo("zero");
        assertThat(table.get("\u0001")).isEqualTo("one");
        assertThat(table.get("")).isEqualTo("empty");
        assertThat(table.remove("f5a5a608")).isEqualTo("zero");
        assertThat(table.get("f5a5a608")).isNull();
        assertThat(table.get("\u0001")).isEqualTo("one");
        assertThat(table.get("")).isEqualTo("empty");
        assertThat(table.size()).isEqualTo(2);
    }
}
