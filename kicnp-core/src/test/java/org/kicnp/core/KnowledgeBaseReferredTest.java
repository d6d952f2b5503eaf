package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.kicnp.core.Frames.cls;
import static org.kicnp.core.Frames.root;

import java.util.List;
import java.util.function.BiFunction;
import org.junit.jupiter.api.Test;

/**
 * {@link KnowledgeBase#add(Frame, Frame...)} reaches the frames a new frame refers to through frames the caller has at
 * hand; it must do exactly what {@link KnowledgeBase#add(Frame)} does, whatever became of those frames.
 */
class KnowledgeBaseReferredTest {

    /** Classes Thing, Stim (a Thing), Other, Pair (mA: Stim, mB: Stim); instances s1, s2 of Stim and o1 of Other. */
    private static KnowledgeBase kb() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(root("Thing"));
        kb.add(cls("Stim", "Thing"));
        kb.add(cls("Other", "Thing"));
        kb.add(Frame.classFrame("Pair").slot(Frames.instanceSlot("mA", "Stim"))
                .slot(Frames.instanceSlot("mB", "Stim")).build());
        kb.add(instance("s1", "Stim"));
        kb.add(instance("s2", "Stim"));
        kb.add(instance("o1", "Other"));
        return kb;
    }

    private static Frame instance(String name, String cls) {
        return Frame.instance(name, cls).provenance(Provenance.RUNTIME).build();
    }

    private static Frame pair(String name, String a, String b) {
        return Frame.instance(name, "Pair").provenance(Provenance.RUNTIME)
                .slot(Slot.builder("mA", DataType.INSTANCE).value(Value.ref(a)).build())
                .slot(Slot.builder("mB", DataType.INSTANCE).value(Value.ref(b)).build()).build();
    }

    /**
     * Adds {@code frame} to two knowledge bases made alike, to one by name and to the other with the frames
     * {@code setUp} picks from it at hand, and checks both end alike: the same refusal message, or the same frames
     * and referrers.
     */
    private static void assertSameOutcome(BiFunction<KnowledgeBase, KnowledgeBase, Frame[]> setUp, Frame frame) {
        KnowledgeBase byName = kb();
        KnowledgeBase withReferred = kb();
        Frame[] referred = setUp.apply(withReferred, byName);
        String expected = outcome(() -> byName.add(frame));
        String actual = outcome(() -> withReferred.add(frame, referred));
        assertThat(actual).isEqualTo(expected);
        assertThat(withReferred.frames()).isEqualTo(byName.frames());
        for (Frame f : byName.frames()) {
            assertThat(withReferred.referrers(f.name())).as(f.name()).isEqualTo(byName.referrers(f.name()));
        }
    }

    private static String outcome(Runnable add) {
        try {
            add.run();
            return "added";
        } catch (BatchRejectedException e) {
            return e.getMessage();
        }
    }

    @Test
    void add_withTheReferredFramesAtHand_addsAndIndexesAsByName() {
        assertSameOutcome((kb, other) -> new Frame[] {kb.require("s1"), kb.require("s2")}, pair("P-1", "s1", "s2"));
        KnowledgeBase kb = kb();
        kb.add(pair("P-1", "s1", "s2"), kb.require("s1"), null, kb.require("s2"));
        assertThat(kb.referrers("s1")).containsExactly("P-1");
        assertThat(kb.referrers("s2")).containsExactly("P-1");
    }

    @Test
    void add_whenAFrameAtHandWasRemoved_refusesAsByName() {
        assertSameOutcome((kb, other) -> {
            Frame s1 = kb.require("s1");
            kb.remove("s1");
            other.remove("s1");
            return new Frame[] {s1, kb.require("s2")};
        }, pair("P-1", "s1", "s2"));
        KnowledgeBase kb = kb();
        Frame s1 = kb.require("s1");
        kb.remove("s1");
        assertThatThrownBy(() -> kb.add(pair("P-1", "s1", "s2"), s1, kb.require("s2")))
                .isInstanceOf(BatchRejectedException.class)
                .hasMessage("Slot 'mA' of frame 'P-1' refers to 's1', which is not defined.");
    }

    @Test
    void add_whenANameAtHandWasRemovedAndAddedAgainAsAnotherClass_refusesAsByName() {
        assertSameOutcome((kb, other) -> {
            Frame s1 = kb.require("s1");
            for (KnowledgeBase k : List.of(kb, other)) {
                k.remove("s1");
                k.add(instance("s1", "Other"));
            }
            return new Frame[] {s1, kb.require("s2")};
        }, pair("P-1", "s1", "s2"));
        KnowledgeBase kb = kb();
        Frame s1 = kb.require("s1");
        kb.remove("s1");
        kb.add(instance("s1", "Other"));
        assertThatThrownBy(() -> kb.add(pair("P-1", "s1", "s2"), s1))
                .isInstanceOf(BatchRejectedException.class)
                .hasMessage("Slot 'mA' of frame 'P-1' must hold an instance of 'Stim', but 's1' is not one.");
    }

    @Test
    void add_whenAFrameAtHandWasReplaced_checksTheFrameTheKnowledgeBaseHoldsNow() {
        assertSameOutcome((kb, other) -> {
            Frame s1 = kb.require("s1");
            kb.replace(instance("s1", "Other"));
            other.replace(instance("s1", "Other"));
            return new Frame[] {s1};
        }, pair("P-1", "s1", "s2"));
        assertSameOutcome((kb, other) -> {
            Frame s1 = kb.require("s1");
            Frame s1Again = Frame.instance("s1", "Stim").provenance(Provenance.RUNTIME)
                    .slot(Frames.str("note", "x")).build();
            kb.replace(s1Again);
            other.replace(s1Again);
            return new Frame[] {s1};
        }, pair("P-1", "s1", "s2"));
    }

    @Test
    void add_withFramesAtHandFromAnotherKnowledgeBaseOrNamingOthers_isAsByName() {
        assertSameOutcome((kb, other) -> new Frame[] {kb().require("s1"), instance("s2", "Other")},
                pair("P-1", "s1", "s2"));
        assertSameOutcome((kb, other) -> new Frame[] {kb.require("o1")}, pair("P-1", "o1", "s2"));
        assertSameOutcome((kb, other) -> new Frame[] {kb.require("s1")}, pair("P-1", "s1", "ghost"));
        assertSameOutcome((kb, other) -> new Frame[] {kb.require("s1"), kb.require("s2")}, pair("s2", "s1", "s1"));
    }
}
