package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;

/**
 * For tests that run the same changes on twin knowledge bases — one taking a short cut, one
 * {@linkplain KnowledgeBase#withoutShortCuts without short cuts} — and require them to end alike.
 */
final class TwinKnowledgeBases {
    private TwinKnowledgeBases() {
    }

    /**
     * The twins' knowledge base: Thing; Stim (key) below it with StimA, StimB; Derived; Pair (mA: StimA, mB: StimB);
     * Triple, a Pair (mC: Stim); the instance inst of Thing; stimuli s1 to s6 (StimA for odd numbers, else StimB).
     */
    static KnowledgeBase kb() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.apply(List.of(
                new Change.Add(Frames.root("Thing")),
                new Change.Add(Frame.classFrame("Stim").parent("Thing")
                        .slot(Slot.builder("key", DataType.INTEGER).build()).build()),
                new Change.Add(Frames.cls("StimA", "Stim")),
                new Change.Add(Frames.cls("StimB", "Stim")),
                new Change.Add(Frames.root("Derived")),
                new Change.Add(Frame.classFrame("Pair").parent("Derived")
                        .slot(Frames.instanceSlot("mA", "StimA")).slot(Frames.instanceSlot("mB", "StimB")).build()),
                new Change.Add(Frame.classFrame("Triple").parent("Pair")
                        .slot(Frames.instanceSlot("mC", "Stim")).build()),
                new Change.Add(Frame.instance("inst", "Thing").build())));
        for (int i = 1; i <= 6; i++) {
            kb.add(stimulus("s" + i, i % 2 == 0 ? "StimB" : "StimA"));
        }
        return kb;
    }

    static Frame stimulus(String name, String cls) {
        return Frame.instance(name, cls).provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("key", DataType.INTEGER, Value.of(1))).build();
    }

    /** "done", or the refusal's class and message: what two twins must answer alike. */
    static String outcome(Runnable change) {
        try {
            change.run();
            return "done";
        } catch (KnowledgeException e) {
            return e.getClass().getSimpleName() + ": " + e.getMessage();
        }
    }

    /** The same frames, version, revisions, referrers, children and instances of every class. */
    static void assertSameState(KnowledgeBase quick, KnowledgeBase general) {
        assertThat(quick.frames()).isEqualTo(general.frames());
        assertThat(quick.version()).isEqualTo(general.version());
        for (Frame f : general.frames()) {
            String n = f.name();
            assertThat(quick.revision(n)).as("revision of %s", n).isEqualTo(general.revision(n));
            assertThat(quick.referrers(n)).as("referrers of %s", n).isEqualTo(general.referrers(n));
            assertThat(quick.children(n)).as("children of %s", n).isEqualTo(general.children(n));
            if (f.isClass()) {
                assertThat(quick.instancesOf(n)).as("instances of %s", n).isEqualTo(general.instancesOf(n));
            }
        }
    }

    /** Frames at hand for an add: some live, some removed since, some of another {@link #kb()}; nulls too. */
    static Frame[] referred(Random r, KnowledgeBase kb, List<Frame> removed) {
        List<Frame> live = kb.frames();
        Frame[] out = new Frame[r.nextInt(4)];
        for (int i = 0; i < out.length; i++) {
            int from = r.nextInt(10);
            out[i] = from == 0 || removed.isEmpty() && from < 3 ? null
                    : from < 3 ? removed.get(r.nextInt(removed.size()))
                    : from == 3 ? kb().require("s" + (1 + r.nextInt(6)))
                    : live.get(r.nextInt(live.size()));
        }
        return out;
    }
}
