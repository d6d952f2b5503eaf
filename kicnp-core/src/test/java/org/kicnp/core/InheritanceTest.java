package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;

class InheritanceTest {

    private static KnowledgeBase robots() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.apply(List.of(
                new Change.Add(Frame.classFrame("Robot")
                        .slot(Slot.builder("speed", DataType.FLOAT).value(Value.of(0.5)).role("m/s").build())
                        .slot(Slot.builder("name", DataType.STRING).defaultValue(Value.of("robot")).build())
                        .slot(Slot.builder("owner", DataType.STRING).required(true).build())
                        .build()),
                new Change.Add(Frame.classFrame("HumanoidRobot").parent("Robot")
                        .slot(Slot.builder("speed", DataType.FLOAT).defaultValue(Value.of(0.25)).build())
                        .build()),
                new Change.Add(Frame.instance("PINO", "HumanoidRobot")
                        .slot(Slot.ofValue("name", DataType.STRING, Value.of("PINO")))
                        .build()),
                new Change.Add(Frame.instance("Robovie", "HumanoidRobot").build())));
        return kb;
    }

    @Test
    void slot_isLookedUpOnTheFrameThenUpTheChain() {
        KnowledgeBase kb = robots();
        EffectiveSlot owner = kb.slot("PINO", "owner").orElseThrow();
        assertThat(owner.declaredBy()).isEqualTo("Robot");
        assertThat(owner.slot().required()).isTrue();
        assertThat(kb.slot("PINO", "missing")).isEmpty();
    }

    @Test
    void value_isTheMergedSlotsEffectiveValue_forEveryFrameAndSlot() {
        KnowledgeBase kb = robots();
        for (String frame : List.of("Robot", "HumanoidRobot", "PINO", "Robovie")) {
            for (String slot : List.of("speed", "name", "owner", "missing")) {
                assertThat(kb.value(frame, slot)).as("%s.%s", frame, slot)
                        .isEqualTo(kb.slot(frame, slot).flatMap(e -> e.slot().effectiveValue()));
            }
        }
        assertThat(kb.value("Robovie", "speed")).contains(Value.of(0.25));
        assertThat(kb.value("PINO", "name")).contains(Value.of("PINO"));
        assertThat(kb.value("Robovie", "name")).contains(Value.of("robot"));
        assertThat(kb.value("Robovie", "owner")).isEmpty();
    }

    @Test
    void lowerFrameOverrides_andItsDefaultHidesAnAncestorsValue() {
        KnowledgeBase kb = robots();
        assertThat(kb.value("Robot", "speed")).contains(Value.of(0.5));
        assertThat(kb.value("HumanoidRobot", "speed")).contains(Value.of(0.25));
        assertThat(kb.value("PINO", "speed")).contains(Value.of(0.25));
        EffectiveSlot speed = kb.slot("PINO", "speed").orElseThrow();
        assertThat(speed.declaredBy()).isEqualTo("HumanoidRobot");
        assertThat(speed.valueFrom()).isEqualTo("HumanoidRobot");
    }

    @Test
    void defaultAppliesOnlyWhereNoValueIsGiven() {
        KnowledgeBase kb = robots();
        assertThat(kb.value("PINO", "name")).contains(Value.of("PINO"));
        assertThat(kb.value("Robovie", "name")).contains(Value.of("robot"));
        assertThat(kb.slot("Robovie", "name").orElseThrow().slot().defaultValue()).contains(Value.of("robot"));
        assertThat(kb.slot("PINO", "name").orElseThrow().slot().defaultValue()).isEmpty();
    }

    @Test
    void facetsMissingBelowAreInheritedFromAbove() {
        KnowledgeBase kb = robots();
        assertThat(kb.slot("PINO", "speed").orElseThrow().slot().role()).contains("m/s");
    }

    @Test
    void slots_listsInheritedSlotsTopmostFirstWithTheirSource() {
        KnowledgeBase kb = robots();
        assertThat(kb.slots("PINO")).extracting(e -> e.slot().name() + "@" + e.declaredBy())
                .containsExactly("speed@HumanoidRobot", "name@PINO", "owner@Robot");
    }

    @Test
    void valueAndDefaultBothGiven_isAnError() {
        assertThatThrownBy(() -> Slot.builder("speed", DataType.FLOAT).value(Value.of(1.0))
                .defaultValue(Value.of(2.0)).build())
                .isInstanceOf(InvalidFrameException.class)
                .hasMessage("Slot 'speed' has both a value and a default; the paper allows one or the other (Table 2).");
    }

    @Test
    void valueOfWrongType_isAnError() {
        assertThatThrownBy(() -> Slot.ofValue("speed", DataType.INTEGER, Value.of("fast")))
                .hasMessage("The value 'fast' of slot 'speed' is not of its type TYPE_INT.");
    }

    @Test
    void editingAnAncestor_isSeenByDescendantsAtOnce() {
        KnowledgeBase kb = robots();
        Frame robot = kb.require("Robot");
        kb.replace(robot.withSlot(Slot.builder("name", DataType.STRING).defaultValue(Value.of("unit")).build()));
        assertThat(kb.value("Robovie", "name")).contains(Value.of("unit"));
    }
}
