package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@link Frame#instance(String, String, Provenance, Slot...)}, the engine's way to make each firing's instance: the
 * frame the builder makes from the same parts, with the builder's checks and messages (and two slots of one name
 * refused rather than the last kept).
 */
class FrameInstanceTest {
    private static final Slot A = Slot.ofValue("mA", DataType.INSTANCE, Value.ref("s1"));
    private static final Slot B = Slot.ofValue("mB", DataType.INSTANCE, Value.ref("s2"));
    private static final Slot KEY = Slot.ofValue("key", DataType.INTEGER, Value.of(3));

    private static Frame built(String name, String cls, Provenance p, Slot... slots) {
        Frame.Builder b = Frame.instance(name, cls).provenance(p);
        for (Slot s : slots) {
            b.slot(s);
        }
        return b.build();
    }

    @Test
    void makesTheFrameTheBuilderMakes() {
        for (List<Slot> slots : List.of(List.<Slot>of(), List.of(A), List.of(A, B), List.of(KEY, A, B))) {
            Slot[] array = slots.toArray(Slot[]::new);
            for (Provenance p : List.of(Provenance.RUNTIME, Provenance.LEARNED)) {
                Frame made = Frame.instance("Pair-7", "Pair", p, array);
                Frame expected = built("Pair-7", "Pair", p, array);
                assertThat(made).isEqualTo(expected).hasSameHashCodeAs(expected);
                assertThat(made.slots()).isEqualTo(slots);
                assertThat(made.parentOrNull()).isEqualTo("Pair");
                assertThat(made.isInstance()).isTrue();
                assertThat(made.provenance()).isEqualTo(p);
                assertThat(made.parts()).isEmpty();
                assertThat(made.linksTo()).isEmpty();
                assertThat(made.linksFrom()).isEmpty();
            }
        }
        assertThat(Frame.instance("  Pair-7 ", "Pair", Provenance.RUNTIME, A)).as("the name is stripped, as built")
                .isEqualTo(built("Pair-7", "Pair", Provenance.RUNTIME, A));
    }

    @Test
    void keepsNoReferenceToTheCallersArray() {
        Slot[] slots = {A, B};
        Frame made = Frame.instance("Pair-7", "Pair", Provenance.RUNTIME, slots);
        slots[0] = KEY;
        assertThat(made.slots()).containsExactly(A, B);
    }

    @Test
    void refusesWhatTheBuilderRefuses_withItsMessages() {
        for (String name : List.of("", "7up", "a b")) {
            assertThatThrownBy(() -> Frame.instance(name, "Pair", Provenance.RUNTIME, A))
                    .isInstanceOf(InvalidFrameException.class)
                    .hasMessage(messageOf(() -> built(name, "Pair", Provenance.RUNTIME, A)));
        }
        assertThatThrownBy(() -> Frame.instance("Pair", "Pair", Provenance.RUNTIME))
                .isInstanceOf(InvalidFrameException.class).hasMessage("Frame 'Pair' cannot be a kind of itself.");
    }

    @Test
    void refusesTwoSlotsOfOneName() {
        Slot again = Slot.ofValue("mA", DataType.INSTANCE, Value.ref("s9"));
        assertThatThrownBy(() -> Frame.instance("Pair-7", "Pair", Provenance.RUNTIME, A, B, again))
                .isInstanceOf(InvalidFrameException.class).hasMessage("Frame 'Pair-7' has two slots named 'mA'.");
    }

    @Test
    void refusesNulls() {
        assertThatThrownBy(() -> Frame.instance(null, "Pair", Provenance.RUNTIME)).isInstanceOf(NullPointerException.class);
        assertThatThrownBy(() -> Frame.instance("P-1", null, Provenance.RUNTIME)).isInstanceOf(NullPointerException.class);
        assertThatThrownBy(() -> Frame.instance("P-1", "Pair", null)).isInstanceOf(NullPointerException.class);
        assertThatThrownBy(() -> Frame.instance("P-1", "Pair", Provenance.RUNTIME, A, null))
                .isInstanceOf(NullPointerException.class);
    }

    private static String messageOf(Runnable r) {
        try {
            r.run();
        } catch (InvalidFrameException e) {
            return e.getMessage();
        }
        throw new AssertionError("the builder accepted it");
    }
}
