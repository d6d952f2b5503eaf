package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;
import org.kicnp.core.UnknownFrameException;

class WhyNotTest {

    @Test
    void whyNot_whenASlotHasNoInstanceOfItsClass_namesTheSlotAndTheClass() {
        Fixture f = Fixture.paper();
        InferenceEngine e = f.engine();
        f.assertFact("mouth1", "Mouth");
        e.runToQuiescence();

        WhyNot w = e.whyNot("Greeting", Map.of());

        assertThat(w.slots()).extracting(WhyNot.SlotCandidates::slot, WhyNot.SlotCandidates::candidates)
                .containsExactly(org.assertj.core.groups.Tuple.tuple("mUser", java.util.List.of()),
                        org.assertj.core.groups.Tuple.tuple("mMouth", java.util.List.of("mouth1")));
        assertThat(w.bindings()).isEmpty();
        assertThat(w.summary()).isEqualTo("'Greeting' cannot fire: nothing can fill its slot 'mUser' (there is no "
                + "instance of 'KnownUser').");
    }

    @Test
    void whyNot_whenTheOnlyCandidatesFailTheSlotsOwnCondition_saysSoWithTheValuesTested() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Order", null);
        f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mOrder", "Order", ".drink == \"tea\"")).build());
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User");
        f.assertFact("o1", "Order", "drink", "coffee");
        e.runToQuiescence();

        WhyNot w = e.whyNot("Deliver", Map.of());

        assertThat(w.slots().get(1).rejected()).containsExactly("o1: .drink == \"tea\" is false ('o1'.drink is "
                + "coffee)");
        assertThat(w.summary()).isEqualTo("'Deliver' cannot fire: nothing can fill its slot 'mOrder' (1 instance of "
                + "'Order' exists but its condition .drink == \"tea\" turns it away).");
    }

    @Test
    void whyNot_ofAJoinThatDoesNotHold_givesTheBindingAndTheSlotWhoseConditionIsFalse() {
        Fixture f = pairs();
        InferenceEngine e = f.engine();
        f.assertFact("a1", "A", "key", 1L);
        f.assertFact("b2", "B", "key", 2L);
        e.runToQuiescence();

        WhyNot w = e.whyNot("Pair", Map.of());

        assertThat(w.bindings()).singleElement().satisfies(v -> {
            assertThat(v.binding()).containsExactly(Map.entry("mA", "a1"), Map.entry("mB", "b2"));
            assertThat(v.outcome()).isEqualTo(WhyNot.Outcome.CONDITION_FALSE);
            assertThat(v.reason()).isEqualTo("slot 'mB': .key == mA.key is false ('b2'.key is 2)");
        });
        assertThat(w.summary()).isEqualTo("'Pair' has 1 binding: 1 fails a condition.");
    }

    @Test
    void whyNot_tellsFiredWaitingAndNotYetMatchedBindingsApart_andChangesNothing() {
        Fixture f = pairs();
        InferenceEngine e = f.engine();
        f.assertFact("a1", "A", "key", 1L);
        f.assertFact("b1", "B", "key", 1L);
        e.runToQuiescence();
        f.assertFact("b1x", "B", "key", 1L); // matched by the engine when it next processes its queue: waiting
        int frames = f.kb.size();

        WhyNot w = e.whyNot("Pair", Map.of());

        assertThat(w.bindings()).extracting(v -> v.binding().get("mB"), WhyNot.Verdict::outcome).containsExactly(
                org.assertj.core.groups.Tuple.tuple("b1", WhyNot.Outcome.BLOCKED),
                org.assertj.core.groups.Tuple.tuple("b1x", WhyNot.Outcome.WAITING));
        assertThat(w.bindings().getFirst().reason()).isEqualTo("refraction: this binding has already fired");
        assertThat(w.summary()).isEqualTo("'Pair' has 2 bindings: 1 blocked, 1 waiting on the agenda.");
        assertThat(f.kb.size()).as("nothing created").isEqualTo(frames);
        assertThat(f.instancesOf("Pair")).hasSize(1);
        assertThat(e.agendaSize()).isEqualTo(1);
    }

    @Test
    void whyNot_ofAnUnsharedSlotsInstance_namesTheInstanceThatHoldsIt() {
        Fixture f = new Fixture();
        f.cls("Robot", null).cls("Cup", null);
        f.kb.add(Frame.classFrame("Serve").slot(Fixture.inst("mRobot", "Robot"))
                .slot(Slot.builder("mCup", DataType.INSTANCE).argument("Cup").required(true).shared(false).build())
                .build());
        InferenceEngine e = f.engine();
        f.assertFact("cup1", "Cup");
        f.assertFact("r1", "Robot");
        e.runToQuiescence();
        f.assertFact("r2", "Robot");
        e.runToQuiescence();
        String made = f.instancesOf("Serve").getFirst();

        WhyNot w = e.whyNot("Serve", Map.of("mRobot", "r2"));

        assertThat(w.slots().getFirst().candidates()).containsExactly("r2");
        assertThat(w.bindings()).singleElement().satisfies(v -> {
            assertThat(v.outcome()).isEqualTo(WhyNot.Outcome.BLOCKED);
            assertThat(v.reason()).isEqualTo("unshared slot 'mCup' already holds 'cup1' in '" + made + "'");
        });
    }

    @Test
    void whyNot_ofABindingWithAScriptCondition_runsItAndSaysItIsFalse_andADestroyedInstancesBindingStaysRefracted() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Mouth", null);
        f.kb.add(Frame.classFrame("Talk").slot(Fixture.inst("mUser", "User", "js: old-enough"))
                .slot(Fixture.inst("mMouth", "Mouth")).build());
        f.kb.add(Frame.classFrame("Listen").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mMouth", "Mouth")).build());
        f.scripts.define("old-enough", g -> false);
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User");
        f.assertFact("m1", "Mouth");
        e.runToQuiescence();
        int calls = f.scripts.calls("old-enough");
        e.destroy(f.instancesOf("Listen").getFirst());

        WhyNot talk = e.whyNot("Talk", Map.of());

        assertThat(talk.bindings()).singleElement().satisfies(v -> {
            assertThat(v.outcome()).isEqualTo(WhyNot.Outcome.SCRIPT_CONDITION);
            assertThat(v.reason()).isEqualTo("the script condition of slot 'mUser' is false");
        });
        assertThat(talk.summary()).contains("1 fails a script condition");
        assertThat(f.scripts.calls("old-enough")).as("whyNot runs it once, for the one binding").isEqualTo(calls + 1);
        assertThat(f.instancesOf("Talk")).isEmpty();
        assertThat(e.whyNot("Listen", Map.of()).bindings()).as("the same binding never fires twice")
                .singleElement().satisfies(v -> assertThat(v.outcome()).isEqualTo(WhyNot.Outcome.BLOCKED));
    }

    @Test
    void whyNot_ofAScriptConditionThatThrows_givesTheScriptsError() {
        Fixture f = new Fixture();
        f.cls("User", null);
        f.kb.add(Frame.classFrame("Talk").slot(Fixture.inst("mUser", "User", "js: broken")).build());
        f.scripts.define("broken", g -> {
            throw new IllegalStateException("s.mUser.profile is undefined");
        });
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User");
        e.runToQuiescence();

        f.assertFact("u2", "User");
        WhyNot talk = e.whyNot("Talk", Map.of());

        assertThat(talk.bindings()).hasSize(2).allSatisfy(v -> {
            assertThat(v.outcome()).isEqualTo(WhyNot.Outcome.SCRIPT_CONDITION);
            assertThat(v.reason()).isEqualTo("the script condition of slot 'mUser' failed: s.mUser.profile is undefined");
        });
        assertThat(talk.summary()).isEqualTo("'Talk' has 2 bindings: 2 fail a script condition.");
    }

    @Test
    void whyNot_ofAScriptConditionThatHoldsNowButDidNotWhenMatched_saysTheBindingIsNotMatchedAgainByWhatTheScriptReads() {
        Fixture f = new Fixture();
        f.cls("User", null);
        f.kb.add(Frame.classFrame("Talk").slot(Fixture.inst("mUser", "User", "js: open")).build());
        boolean[] open = {false}; // something the script reads that is no instance of the binding
        f.scripts.define("open", g -> open[0]);
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User");
        e.runToQuiescence();
        open[0] = true;

        assertThat(e.whyNot("Talk", Map.of()).bindings()).singleElement().satisfies(v -> {
            assertThat(v.outcome()).isEqualTo(WhyNot.Outcome.WOULD_FIRE);
            assertThat(v.reason()).startsWith("its script conditions hold now, but not when the engine matched the "
                    + "binding");
        });
        assertThat(e.runToQuiescence()).as("as said: nothing matches it again").isZero();
    }

    @Test
    void whyNot_withAPartialBinding_keepsThatSlot_andRejectsAnInstanceOfTheWrongClass() {
        Fixture f = Fixture.paper();
        InferenceEngine e = f.engine();
        f.assertFact("mouth1", "Mouth");
        f.assertFact("mouth2", "Mouth");
        f.assertFact("taro", "KnownUser");
        e.runToQuiescence();

        assertThat(e.whyNot("Greeting", Map.of("mMouth", "mouth2")).bindings())
                .extracting(v -> v.binding().get("mMouth")).containsExactly("mouth2");
        WhyNot wrong = e.whyNot("Greeting", Map.of("mUser", "mouth1"));
        assertThat(wrong.slots().getFirst().rejected()).containsExactly("mouth1: not an instance of 'KnownUser'");
        assertThat(wrong.bindings()).isEmpty();
    }

    @Test
    void whyNot_refusesInWords_anUnknownFrame_aFrameThatIsNotABehaviorFrame_andASlotItDoesNotRequire() {
        Fixture f = Fixture.paper();
        InferenceEngine e = f.engine();
        f.assertFact("mouth1", "Mouth");

        assertThatThrownBy(() -> e.whyNot("Nothing", Map.of())).isInstanceOf(UnknownFrameException.class);
        assertThatThrownBy(() -> e.whyNot("User", Map.of())).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("Frame 'User' is not a behavior frame: it has no required instance slot, so the engine "
                        + "never fires it.");
        assertThatThrownBy(() -> e.whyNot("mouth1", Map.of())).hasMessageContaining("'mouth1' is an instance");
        assertThatThrownBy(() -> e.whyNot("Greeting", Map.of("mRobot", "mouth1")))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("Frame 'Greeting' has no required instance slot 'mRobot'; its required slots are "
                        + "[mUser, mMouth].");
    }

    @Test
    void whyNot_stopsAtTheEnginesAnswerLimit_andSaysItDid() {
        Fixture f = pairs();
        InferenceEngine e = f.engine(new EngineOptions(10_000, Duration.ofSeconds(30), 8, 3));
        for (int i = 0; i < 3; i++) {
            f.assertFact("a" + i, "A", "key", (long) i);
            f.assertFact("b" + i, "B", "key", 100L + i);
        }
        e.runToQuiescence();

        WhyNot w = e.whyNot("Pair", Map.of());

        assertThat(w.bindings()).hasSize(3);
        assertThat(w.truncated()).isTrue();
        assertThat(w.slots().getFirst().candidates()).as("listed up to the limit").hasSize(3);
        assertThat(w.slots().getFirst().candidateCount()).isEqualTo(3);
        assertThat(w.summary()).isEqualTo("'Pair' has more than 3 bindings: 3 fail a condition.");
    }

    @Test
    void whyNot_listsCandidatesAndTurnedAwayInstancesUpToTheLimit_andCountsThemAll() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Order", null);
        f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mOrder", "Order", ".drink == \"tea\"")).build());
        InferenceEngine e = f.engine(new EngineOptions(10_000, Duration.ofSeconds(30), 8, 2));
        for (int i = 0; i < 5; i++) {
            f.assertFact("u" + i, "User");
            f.assertFact("o" + i, "Order", "drink", "coffee");
        }
        e.runToQuiescence();

        WhyNot w = e.whyNot("Deliver", Map.of());

        assertThat(w.slots().get(0).candidates()).containsExactly("u0", "u1");
        assertThat(w.slots().get(0).candidateCount()).isEqualTo(5);
        assertThat(w.slots().get(1).rejected()).hasSize(2);
        assertThat(w.slots().get(1).rejectedCount()).isEqualTo(5);
        assertThat(w.summary()).isEqualTo("'Deliver' cannot fire: nothing can fill its slot 'mOrder' (5 instances of "
                + "'Order' exist but its condition .drink == \"tea\" turns them all away).");
    }

    /** Pair(mA: A, mB: B) joined on equal keys. */
    private static Fixture pairs() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("Keyed").slot(Slot.builder("key", DataType.INTEGER).build()).build());
        f.cls("A", "Keyed").cls("B", "Keyed");
        f.kb.add(Frame.classFrame("Pair").slot(Fixture.inst("mA", "A"))
                .slot(Fixture.inst("mB", "B", ".key == mA.key")).build());
        return f;
    }
}
