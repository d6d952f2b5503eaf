package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.NameTable;

class MadeInstancesTest {

    /** The engine hands the number on to its fact records instead of reading it off the name: they must agree. */
    @Test
    void number_isTheNumberTheNameEndsIn_upToNineDigits() {
        for (long start : List.of(0L, 41L, 999_999_990L, 2_147_483_640L)) {
            MadeInstances made = new MadeInstances(KnowledgeBase.create(), start);
            for (int i = 0; i < 20; i++) {
                for (String prefix : List.of("Pair", "A-", "x9", "a-b")) {
                    String name = made.next(prefix);
                    assertThat(made.number()).as(name).isEqualTo(NameTable.numberOf(name));
                }
            }
        }
    }

    @Test
    void fresh_skipsTakenNames_andItsNumberIsTheFreshName() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.put(org.kicnp.core.Frame.classFrame("Pair").build());
        kb.put(org.kicnp.core.Frame.instance("Pair-1", "Pair").build());
        MadeInstances made = new MadeInstances(kb);

        String name = made.fresh("Pair");

        assertThat(name).isEqualTo("Pair-2");
        assertThat(made.number()).isEqualTo(2);
    }
}
