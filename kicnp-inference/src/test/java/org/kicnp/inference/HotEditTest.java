package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.ref.WeakReference;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Change;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * Frames edited, added or removed while the engine runs take effect at once, with no restart: the instances already
 * there are checked again against the changed frame or class, claims and refraction follow the edited rule, and a
 * new behavior frame matches what is there (docs/inference.md §8). Split from {@link TruthMaintenanceTest}, whose
 * subject is what a retraction takes with it.
 */
class HotEditTest {

    @Test
    void hotEdit_whenFrameConditionChanges_existingInstancesAreRecheckedAtOnce() {
        Fixture f = new Fixture();
        f.cls("Order", null);
        f.kb.add(Frame.classFrame("Serve").slot(Fixture.inst("mOrder", "Order")).build());
        InferenceEngine e = f.engine();
        f.assertFact("o1", "Order", "drink", "tea");
        f.assertFact("o2", "Order", "drink", "coffee");
        e.runToQuiescence();
        assertThat(f.instancesOf("Serve")).hasSize(2);

        f.kb.replace(f.kb.require("Serve").withSlot(Fixture.inst("mOrder", "Order", ".drink == \"tea\"")));
        e.runToQuiescence();
        assertThat(f.instancesOf("Serve")).singleElement()
                .satisfies(n -> assertThat(f.kb.value(n, "mOrder")).contains(Value.ref("o1")));
    }

    private static Slot cupSlot(boolean shared) {
        return Slot.builder("mCup", DataType.INSTANCE).argument("Cup").required(true).shared(shared).build();
    }

    @Test
    void hotEdit_whenASlotBecomesUnshared_theInstanceItHoldsAlreadyIsConsumed() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Cup", null);
        f.kb.add(Frame.classFrame("Serve").slot(Fixture.inst("mUser", "User")).slot(cupSlot(true)).build());
        InferenceEngine e = f.engine();
        f.assertFact("cup", "Cup");
        f.assertFact("u1", "User");
        e.runToQuiescence();
        assertThat(f.instancesOf("Serve")).hasSize(1);

        f.kb.replace(f.kb.require("Serve").withSlot(cupSlot(false)));
        f.assertFact("u2", "User");
        e.runToQuiescence();

        assertThat(f.instancesOf("Serve")).as("the cup fills the unshared slot of one live Serve only").hasSize(1);
    }

    /** {@code Serve(mUser: User, mCup: Cup)}, its cup slot shared or not, with one cup and users u1 and u2, run. */
    private record Served(Fixture f, InferenceEngine e) {
        static Served twoUsersOneCup(boolean shared) {
            Fixture f = new Fixture();
            f.cls("User", null).cls("Cup", null);
            f.kb.add(Frame.classFrame("Serve").slot(Fixture.inst("mUser", "User")).slot(cupSlot(shared)).build());
            InferenceEngine e = f.engine();
            f.assertFact("cup", "Cup");
            f.assertFact("u1", "User");
            f.assertFact("u2", "User");
            e.runToQuiescence();
            return new Served(f, e);
        }
    }

    @Test
    void hotEdit_whenASlotBecomesUnshared_aLaterInstanceHoldingTheSameInstanceIsRetracted() {
        Served run = Served.twoUsersOneCup(true);
        Fixture f = run.f();
        InferenceEngine e = run.e();
        List<String> both = f.instancesOf("Serve");
        assertThat(both).hasSize(2);

        f.kb.replace(f.kb.require("Serve").withSlot(cupSlot(false)));
        e.runToQuiescence();

        assertThat(f.instancesOf("Serve")).as("the older firing keeps the cup").containsExactly(both.getFirst());
        assertThat(f.traced(TraceEvent.Retracted.class)).anySatisfy(r -> {
            assertThat(r.instance()).isEqualTo(both.get(1));
            assertThat(r.reason()).isEqualTo("frame 'Serve' changed and its unshared slot 'mCup' already holds 'cup' in '"
                    + both.getFirst() + "'");
        });
    }

    @Test
    void hotEdit_whenAnUnsharedSlotBecomesShared_theBindingsItBlockedFire() {
        Served run = Served.twoUsersOneCup(false);
        Fixture f = run.f();
        InferenceEngine e = run.e();
        assertThat(f.instancesOf("Serve")).hasSize(1);

        f.kb.replace(f.kb.require("Serve").withSlot(cupSlot(true)));
        e.runToQuiescence();

        assertThat(f.instancesOf("Serve")).as("a shared cup serves both users").hasSize(2);
    }

    @Test
    void hotEdit_whenTheSlotsAreReordered_aBindingThatFiredDoesNotFireAgain() {
        Fixture f = new Fixture();
        f.cls("A", null).cls("B", null);
        Slot mA = Slot.builder("mA", DataType.INSTANCE).argument("A").required(true).build();
        Slot mB = Slot.builder("mB", DataType.INSTANCE).argument("B").required(true).build();
        f.kb.add(Frame.classFrame("Pair").slot(mA).slot(mB).build());
        InferenceEngine e = f.engine();
        f.assertFact("a1", "A");
        f.assertFact("b1", "B");
        e.runToQuiescence();
        assertThat(f.instancesOf("Pair")).hasSize(1);

        f.kb.replace(Frame.classFrame("Pair").slot(mB).slot(mA).build());
        e.runToQuiescence();

        assertThat(f.instancesOf("Pair")).as("the same binding, still refracted").hasSize(1);
    }

    @Test
    void classEdit_whenInheritedDefaultChanges_rechecksItsInstances() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("Order").slot(Slot.builder("drink", DataType.STRING).defaultValue(Value.of("tea"))
                .build()).build());
        f.kb.add(Frame.classFrame("ServeTea").slot(Fixture.inst("mOrder", "Order", ".drink == \"tea\"")).build());
        InferenceEngine e = f.engine();
        f.assertFact("o1", "Order");
        e.runToQuiescence();
        assertThat(f.instancesOf("ServeTea")).hasSize(1);
        f.kb.replace(f.kb.require("Order").withSlot(Slot.builder("drink", DataType.STRING)
                .defaultValue(Value.of("coffee")).build()));
        e.runToQuiescence();
        assertThat(f.instancesOf("ServeTea")).isEmpty();
    }

    @Test
    void classEdit_whenADefaultReadThroughAReferenceChanges_rechecksWhatReadsIt() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("Address").slot(Slot.builder("city", DataType.STRING).defaultValue(Value.of("Kyoto"))
                .build()).build());
        f.cls("User", null).cls("Order", null);
        f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mOrder", "Order", ".city == mUser.address.city")).build());
        InferenceEngine e = f.engine();
        f.assertFact("a1", "Address");
        f.assertFact("u1", "User", "address", "@a1");
        f.assertFact("o1", "Order", "city", "Kyoto");
        e.runToQuiescence();
        assertThat(f.instancesOf("Deliver")).hasSize(1);

        f.kb.replace(f.kb.require("Address").withSlot(Slot.builder("city", DataType.STRING)
                .defaultValue(Value.of("Nara")).build()));
        e.runToQuiescence();

        assertThat(f.instancesOf("Deliver")).as("u1's address is in Nara now").isEmpty();
    }

    @Test
    void classEdit_whenClassMovesUnderKnownUser_itsInstancesAreGreeted() {
        Fixture f = Fixture.paper();
        f.kb.add(Frame.classFrame("Taro").parent("User").build());
        InferenceEngine e = f.engine();
        f.assertFact("mouth1", "Mouth");
        f.assertFact("face1", "Taro");
        e.runToQuiescence();
        assertThat(f.instancesOf("Greeting")).isEmpty();
        f.kb.replace(f.kb.require("Taro").toBuilder().parent("KnownUser").build());
        e.runToQuiescence();
        assertThat(f.instancesOf("Greeting")).hasSize(1);
    }

    /**
     * A behavior frame removed with its instances is let go by the engine once the run is over: nothing it keeps
     * between runs (the rules of the last firings, which the firing limit's message names) holds its rule, which
     * holds the frame.
     */
    @Test
    void removingABehaviorFrame_theEngineKeepsNothingOfItAfterTheRun() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("User").build());
        kb.add(Frame.classFrame("Serve").slot(Fixture.inst("mUser", "User")).build());
        kb.add(Frame.instance("u1", "User").provenance(Provenance.RUNTIME).build());
        try (InferenceEngine e = InferenceEngine.builder(kb).build()) {
            assertThat(e.runToQuiescence()).isEqualTo(1);
            WeakReference<Frame> serve = new WeakReference<>(kb.frame("Serve").orElseThrow());
            kb.apply(List.of(new Change.Remove(kb.instancesOf("Serve").getFirst().name()), new Change.Remove("Serve")));
            e.runToQuiescence();

            for (int i = 0; i < 20 && serve.get() != null; i++) {
                System.gc();
            }
            assertThat(serve.get()).as("the removed behavior frame, once collected").isNull();
        }
    }

    @Test
    void removingABehaviorFrameWithItsInstances_runsTheirOnDestroy_whateverOrderTheBatchNamesThem() {
        for (boolean frameFirst : List.of(true, false)) {
            List<String> destroyed = new ArrayList<>();
            Fixture f = new Fixture();
            f.cls("User", null);
            f.kb.add(Frame.classFrame("Serve").slot(Fixture.inst("mUser", "User")).slot(Fixture.str("onDestroy", "bye"))
                    .build());
            f.scripts.define("bye", g -> destroyed.add((String) Fixture.view(g).get("$name")));
            InferenceEngine e = f.engine();
            f.assertFact("u1", "User");
            e.runToQuiescence();
            String serve = f.instancesOf("Serve").getFirst();

            f.kb.apply(frameFirst ? List.of(new Change.Remove("Serve"), new Change.Remove(serve))
                    : List.of(new Change.Remove(serve), new Change.Remove("Serve")));
            e.runToQuiescence();

            assertThat(destroyed).as("frame removed " + (frameFirst ? "before" : "after") + " its instance")
                    .containsExactly(serve);
        }
    }

    @Test
    void hotEdit_whenNewBehaviorFrameIsAdded_matchesInstancesAlreadyThere() {
        Fixture f = Fixture.paper();
        InferenceEngine e = f.engine();
        f.assertFact("mouth1", "Mouth");
        f.assertFact("userA", "NewUser");
        e.runToQuiescence();
        f.kb.add(Frame.classFrame("FaceDetection").parent("Behaviors").slot(Fixture.inst("mUser", "User")).build());
        assertThat(e.runToQuiescence()).isEqualTo(1);
        assertThat(f.instancesOf("FaceDetection")).hasSize(1);
    }
}
