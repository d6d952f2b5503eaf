package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;

/** {@link Slot#withValue} makes what {@code toBuilder().value(v).build()} makes, refusing what it refuses. */
class SlotWithValueTest {

    private static final List<Slot> SLOTS = List.of(
            Slot.builder("mUser", DataType.INSTANCE).argument("User").required(true).unique(true).shared(false)
                    .condition(ConditionParser.parse(".age > 3")).role("listener").from("Robovie").build(),
            Slot.builder("text", DataType.STRING).frameRelated("Speech").frameListRelated(List.of("A", "B"))
                    .reactive(false).onNeeded("1").onAdded("2").onRemoved("3").value(Value.of("hi")).build(),
            Slot.builder("count", DataType.INTEGER).defaultValue(Value.of(2)).build(),
            Slot.builder("speed", DataType.FLOAT).build(),
            Slot.builder("done", DataType.BOOLEAN).build());

    private static final List<Value> VALUES = List.of(Value.ref("ken"), Value.of("hello"), Value.of(7),
            Value.of(0.5), Value.of(true));

    @Test
    void withValue_isTheBuildersSlot_forEveryValueThatFits() {
        int compared = 0;
        for (Slot s : SLOTS) {
            for (Value v : VALUES) {
                Slot built;
                try {
                    built = s.toBuilder().value(v).build();
                } catch (InvalidFrameException e) {
                    continue; // the refusals are compared below
                }
                Slot filled = s.withValue(v);
                assertThat(filled).as("%s with %s", s, v).isEqualTo(built);
                assertThat(filled.valueOrNull()).isEqualTo(v);
                assertThat(filled.onNeeded()).isEqualTo(built.onNeeded());
                assertThat(filled.role()).isEqualTo(built.role());
                compared++;
            }
        }
        assertThat(compared).isEqualTo(5); // its own type's value to each slot but the one with a default; FLOAT an integer too
    }

    @Test
    void withValue_refusesNull_asTheBuilderDoes() {
        assertThatThrownBy(() -> SLOTS.get(3).withValue(null)).isInstanceOf(NullPointerException.class);
        assertThatThrownBy(() -> SLOTS.get(3).toBuilder().value(null)).isInstanceOf(NullPointerException.class);
    }

    @Test
    void withValue_refusesWithTheBuildersMessage_aValueOfAnotherTypeOrBesideADefault() {
        int refused = 0;
        for (Slot s : SLOTS) {
            for (Value v : VALUES) {
                String expected;
                try {
                    s.toBuilder().value(v).build();
                    continue;
                } catch (InvalidFrameException e) {
                    expected = e.getMessage();
                }
                assertThatThrownBy(() -> s.withValue(v)).as("%s with %s", s, v)
                        .isInstanceOf(InvalidFrameException.class).hasMessage(expected);
                refused++;
            }
        }
        assertThat(refused).isEqualTo(VALUES.size() * SLOTS.size() - 5);
        assertThatThrownBy(() -> SLOTS.get(2).withValue(Value.of(3)))
                .hasMessage("Slot 'count' has both a value and a default; the paper allows one or the other (Table 2).");
    }

    /**
     * Slots keep their facets apart from name and value (shared between a slot and those filled from it, and among
     * plain slots of a type): each facet still tells two slots apart, equal slots hash alike, and a plain slot built
     * twice is the same as one filled from a template.
     */
    @Test
    void everyFacetTellsSlotsApart_andEqualSlotsHashAlike_howeverTheirFacetsAreShared() {
        Slot base = Slot.builder("s", DataType.INSTANCE).value(Value.ref("x")).build();
        List<Slot> variants = List.of(
                base.toBuilder().type(DataType.FRAME).build(),
                base.toBuilder().required(true).build(),
                base.toBuilder().shared(false).build(),
                base.toBuilder().unique(true).build(),
                base.toBuilder().reactive(false).build(),
                base.toBuilder().condition(ConditionParser.parse(".age > 3")).build(),
                base.toBuilder().argument("User").build(),
                base.toBuilder().role("listener").build(),
                base.toBuilder().from("Robovie").build(),
                base.toBuilder().frameRelated("Speech").build(),
                base.toBuilder().frameListRelated(List.of("A")).build(),
                base.toBuilder().onNeeded("1").build(),
                base.toBuilder().onAdded("2").build(),
                base.toBuilder().onRemoved("3").build(),
                base.toBuilder().clearValue().defaultValue(Value.ref("y")).build(),
                base.toBuilder().value(Value.ref("z")).build(),
                Slot.builder("t", DataType.INSTANCE).value(Value.ref("x")).build());
        for (Slot v : variants) {
            assertThat(v).as("%s", v).isNotEqualTo(base);
            assertThat(v.toBuilder().build()).isEqualTo(v).hasSameHashCodeAs(v);
        }
        Slot template = Slot.builder("s", DataType.INSTANCE).build();
        assertThat(template.withValue(Value.ref("x"))).isEqualTo(base).hasSameHashCodeAs(base);
        assertThat(Slot.ofValue("s", DataType.INSTANCE, Value.ref("x"))).isEqualTo(base);
        Slot rich = SLOTS.get(0).withValue(Value.ref("ken"));
        assertThat(rich.toBuilder().build()).isEqualTo(rich).hasSameHashCodeAs(rich);
        assertThat(rich.argument()).contains("User");
        assertThat(rich.required() && rich.unique() && !rich.shared() && rich.reactive()).isTrue();
    }

    /**
     * Equal slot names are one String, in slots however they were made and in the paths of conditions: an engine's
     * slot look-ups along a path then compare references (what equals tries first) rather than characters.
     */
    @Test
    void equalSlotNames_areOneString_inSlotsAndInConditionPaths() {
        String parsed = new String(new char[] {'m', 'A'});
        Slot a = Slot.builder(parsed, DataType.INSTANCE).build();
        Slot b = Slot.ofValue(new String("mA"), DataType.INSTANCE, Value.ref("x"));

        assertThat(a.name()).isSameAs(b.name()).isSameAs(b.toBuilder().build().name())
                .isSameAs(a.withValue(Value.ref("y")).name());
        Condition.Compare c = (Condition.Compare) ConditionParser.parse(".key == mA.key");
        List<String> right = ((Operand.Path) c.right()).steps();
        assertThat(right.getFirst()).isSameAs(a.name());
        assertThat(c.left().getFirst()).isSameAs(right.get(1)).isSameAs(Slot.builder("key", DataType.INTEGER)
                .build().name());
    }
}
