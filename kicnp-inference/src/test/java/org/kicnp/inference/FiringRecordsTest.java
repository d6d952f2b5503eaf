package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kicnp.core.ConditionParser;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;

/**
 * What a firing leaves behind, kept in the lean forms the engine uses per firing: the checked conditions (values
 * taken at firing, texts made when read).
 */
class FiringRecordsTest {

    @Test
    void checkedConditions_withAnOptionalSlotLeftEmptyBeforeABoundOne_nameEachBoundSlotWithItsConditionAndValue() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Camera", null).cls("Mic", null);
        f.kb.add(Frame.classFrame("Watch").slot(Fixture.inst("mUser", "User"))
                .slot(Slot.builder("mCam", DataType.INSTANCE).argument("Camera").build())
                .slot(Slot.builder("mMic", DataType.INSTANCE).argument("Mic")
                        .condition(ConditionParser.parse(".level > 3")).build()).build());
        InferenceEngine e = f.engine();
        f.assertFact("mic", "Mic", "level", 5);
        f.assertFact("u1", "User");
        e.runToQuiescence();

        Derivation d = e.derivation(f.instancesOf("Watch").getFirst()).orElseThrow();

        assertThat(d.binding()).containsOnlyKeys("mUser", "mMic");
        assertThat(d.conditions()).containsExactly(new Derivation.CheckedCondition("mUser", "COND_ANY", "u1"),
                new Derivation.CheckedCondition("mMic", ".level > 3", "5"));
        assertThatThrownBy(() -> d.conditions().add(d.conditions().getFirst()))
                .isInstanceOf(UnsupportedOperationException.class);
    }

    @Test
    void checkedConditions_afterTheTestedValueChanges_stillGiveTheValueTestedWhenTheFrameFired() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Order", null);
        f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mOrder", "Order", ".cups > 1")).build());
        InferenceEngine e = f.engine();
        f.assertFact("o1", "Order", "cups", 2);
        f.assertFact("u1", "User");
        e.runToQuiescence();
        String made = f.instancesOf("Deliver").getFirst();

        f.kb.replace(f.kb.require("o1").withSlot(Fixture.num("cups", 3))); // still more than one: the instance stays
        e.runToQuiescence();

        assertThat(f.instancesOf("Deliver")).containsExactly(made);
        assertThat(e.derivation(made).orElseThrow().conditions()).extracting(Derivation.CheckedCondition::value)
                .containsExactly("u1", "2");
    }
}
