package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kicnp.core.BatchRejectedException;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.Slot;
import org.kicnp.core.UnknownFrameException;
import org.kicnp.core.Value;

class TruthMaintenanceTest {

    private static Fixture chainWithOnDestroy(List<String> destroyed) {
        Fixture f = ForwardChainingTest.chain3();
        for (String step : List.of("Step1", "Step2", "Step3")) {
            f.kb.replace(f.kb.require(step).withSlot(Fixture.str("onDestroy", "bye")));
        }
        f.scripts.define("bye", g -> destroyed.add((String) Fixture.view(g).get("$name")));
        return f;
    }

    @Test
    void destroy_whenStimulusGoes_retractsEverythingDerivedFromItAndRunsOnDestroy() {
        List<String> destroyed = new ArrayList<>();
        Fixture f = chainWithOnDestroy(destroyed);
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");
        e.runToQuiescence();
        var derived = new ArrayList<String>();
        for (String c : List.of("Step1", "Step2", "Step3")) {
            derived.addAll(f.instancesOf(c));
        }

        var removed = e.destroy("s1");

        assertThat(removed).containsExactlyInAnyOrderElementsOf(concat("s1", derived));
        assertThat(f.instancesOf("Step1")).isEmpty();
        assertThat(f.instancesOf("Step3")).isEmpty();
        assertThat(destroyed).containsExactlyInAnyOrderElementsOf(derived);
        assertThat(f.traced(TraceEvent.Retracted.class)).extracting(TraceEvent.Retracted::instance)
                .containsAll(derived);
    }

    @Test
    void destroyAtARevision_whenTheInstanceChangedSince_destroysNothing_andAtItsRevisionGoesWithItsReason() {
        List<String> destroyed = new ArrayList<>();
        Fixture f = chainWithOnDestroy(destroyed);
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");
        e.runToQuiescence();
        long read = f.kb.revision("s1");
        f.kb.replace(f.kb.require("s1").withSlot(Fixture.str("note", "a newer reading")));
        e.runToQuiescence();
        List<String> derived = new ArrayList<>(f.instancesOf("Step3"));
        assertThat(derived).hasSize(1);

        assertThatThrownBy(() -> e.destroy("s1", read, "retracted as stale"))
                .isInstanceOf(org.kicnp.core.StaleRevisionException.class);
        assertThat(f.kb.contains("s1")).isTrue();
        assertThat(f.instancesOf("Step3")).isEqualTo(derived);
        assertThat(destroyed).isEmpty();

        var removed = e.destroy("s1", f.kb.revision("s1"), "retracted as stale");
        assertThat(removed).contains("s1").containsAll(derived);
        assertThat(f.traced(TraceEvent.Retracted.class)).contains(
                new TraceEvent.Retracted("s1", "retracted as stale"),
                new TraceEvent.Retracted(derived.getFirst(), "it rests on 's1', which was retracted as stale"));
        assertThat(destroyed).containsAll(derived);
    }

    @Test
    void destroy_ofAClassFrame_isRefusedAsAClassNotAsUnknown_andChangesNothing() {
        Fixture f = ForwardChainingTest.chain3();
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");
        e.runToQuiescence();
        long version = f.kb.version();

        assertThatThrownBy(() -> e.destroy("Step1")).isInstanceOf(KnowledgeException.class)
                .isNotInstanceOf(UnknownFrameException.class)
                .hasMessage("Frame 'Step1' is a class frame; only instances can be destroyed.");
        assertThatThrownBy(() -> e.destroy("Nothing")).isInstanceOf(UnknownFrameException.class)
                .hasMessage("There is no frame named 'Nothing'.");

        assertThat(f.kb.version()).isEqualTo(version);
        assertThat(f.instancesOf("Step3")).hasSize(1);
        assertThat(f.traced(TraceEvent.Retracted.class)).isEmpty();
    }

    @Test
    void removeThroughKnowledgeBase_whenDerivedInstancesReferToIt_isRefusedAllOrNothing() {
        Fixture f = ForwardChainingTest.chain3();
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");
        e.runToQuiescence();
        assertThatThrownBy(() -> f.kb.remove("s1")).isInstanceOf(BatchRejectedException.class);
        assertThat(f.instancesOf("Step3")).hasSize(1);
    }

    @Test
    void destroyMiddle_retractsOnlyWhatRestsOnIt_andRefractionKeepsItFromComingBack() {
        Fixture f = ForwardChainingTest.chain3();
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");
        e.runToQuiescence();
        String step2 = f.instancesOf("Step2").getFirst();
        e.destroy(step2);
        assertThat(f.instancesOf("Step1")).hasSize(1);
        assertThat(f.instancesOf("Step2")).isEmpty();
        assertThat(f.instancesOf("Step3")).isEmpty();
    }

    @Test
    void conditionChange_whenSlotNoLongerSatisfiesCondition_retractsAndRefiresWhenItHoldsAgain() {
        Fixture f = new Fixture();
        f.cls("Order", null);
        f.kb.add(Frame.classFrame("ServeTea").slot(Fixture.inst("mOrder", "Order", ".drink == \"tea\"")).build());
        f.kb.add(Frame.classFrame("Pour").slot(Fixture.inst("mServe", "ServeTea")).build());
        InferenceEngine e = f.engine();
        f.assertFact("o1", "Order", "drink", "tea");
        e.runToQuiescence();
        assertThat(f.instancesOf("Pour")).hasSize(1);

        f.kb.replace(f.kb.require("o1").withSlot(Fixture.str("drink", "coffee")));
        e.runToQuiescence();
        assertThat(f.instancesOf("ServeTea")).isEmpty();
        assertThat(f.instancesOf("Pour")).isEmpty();
        assertThat(f.traced(TraceEvent.Retracted.class)).anySatisfy(r ->
                assertThat(r.reason()).contains("condition of slot 'mOrder' of 'ServeTea' no longer holds"));

        f.kb.replace(f.kb.require("o1").withSlot(Fixture.str("drink", "tea")));
        e.runToQuiescence();
        assertThat(f.instancesOf("ServeTea")).hasSize(1);
        assertThat(f.instancesOf("Pour")).hasSize(1);
    }

    @Test
    void conditionChange_afterTheFiringTookTheNextFreeName_retractsAndRefiresEachTimeItHoldsAgain() {
        Fixture f = new Fixture();
        f.cls("Order", null).cls("Note", null);
        f.kb.add(Frame.classFrame("ServeTea").slot(Fixture.inst("mOrder", "Order", ".drink == \"tea\"")).build());
        f.assertFact("ServeTea-1", "Note"); // the engine's first name for a ServeTea is taken: it takes the next one
        InferenceEngine e = f.engine();
        f.assertFact("o1", "Order", "drink", "tea");
        e.runToQuiescence();
        assertThat(f.instancesOf("ServeTea")).containsExactly("ServeTea-2");

        // Each retraction lets the binding fire again (it is refracted once per firing, the retried name included).
        for (int round = 0; round < 2; round++) {
            f.kb.replace(f.kb.require("o1").withSlot(Fixture.str("drink", "coffee")));
            e.runToQuiescence();
            assertThat(f.instancesOf("ServeTea")).as("round %d, coffee", round).isEmpty();
            f.kb.replace(f.kb.require("o1").withSlot(Fixture.str("drink", "tea")));
            e.runToQuiescence();
            assertThat(f.instancesOf("ServeTea")).as("round %d, tea", round).hasSize(1);
        }
        assertThat(f.traced(TraceEvent.Fired.class)).hasSize(3);
    }

    @Test
    void joinChange_whenPartnerValueChanges_retractsTheJoinedInstance() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Order", null);
        f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mOrder", "Order", ".who == mUser.name")).build());
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User", "name", "Ann");
        f.assertFact("o1", "Order", "who", "Ann");
        e.runToQuiescence();
        assertThat(f.instancesOf("Deliver")).hasSize(1);
        f.kb.replace(f.kb.require("u1").withSlot(Fixture.str("name", "Eve")));
        e.runToQuiescence();
        assertThat(f.instancesOf("Deliver")).isEmpty();
    }

    @Test
    void failingScript_failsThatFiring_discardsItsEffects_andTheEngineCarriesOn() {
        Fixture f = Fixture.paper();
        f.scripts.define("ask-name", g -> {
            Fixture.call(g, "sendmsg", Fixture.view(g).get("mMouth"), "never sent");
            Fixture.call(g, "create", "KnownUser", Map.of());
            throw new IllegalStateException("Script in slot 'onInstantiate' of frame 'AskUserName' ran out of time.");
        });
        InferenceEngine e = f.engine();
        f.assertFact("mouth1", "Mouth");
        f.assertFact("userA", "NewUser");
        e.runToQuiescence();
        assertThat(f.sent).isEmpty();
        assertThat(f.instancesOf("KnownUser")).isEmpty();
        assertThat(f.instancesOf("AskUserName")).isEmpty();
        assertThat(f.traced(TraceEvent.ScriptFailed.class)).singleElement().satisfies(x ->
                assertThat(x.message()).contains("ran out of time"));
        f.assertFact("userB", "NewUser");
        f.scripts.define("ask-name", g -> null);
        assertThat(e.runToQuiescence()).isEqualTo(1);
        assertThat(e.runToQuiescence()).isZero();
    }

    @Test
    void scriptCreatedInstance_restsOnTheInstanceWhoseScriptCreatedIt() {
        Fixture f = Fixture.paper();
        f.kb.add(Frame.classFrame("Note").slot(Slot.builder("text", DataType.STRING).build()).build());
        f.scripts.define("ask-name", g -> Fixture.call(g, "create", "Note", Map.of("text", "asked")));
        InferenceEngine e = f.engine();
        f.assertFact("mouth1", "Mouth");
        f.assertFact("userA", "NewUser");
        e.runToQuiescence();
        String note = f.instancesOf("Note").getFirst();
        assertThat(f.kb.value(note, "text")).contains(Value.of("asked"));
        assertThat(e.why(note).stimuli()).containsExactlyInAnyOrder("userA", "mouth1");
        e.destroy("userA");
        assertThat(f.instancesOf("Note")).isEmpty();
    }

    @Test
    void demonCreatedInstance_restsOnTheInstanceWhoseDemonCreatedIt() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("User").slot(Slot.builder("nick", DataType.STRING).onAdded("note-nick").build())
                .build());
        f.kb.add(Frame.classFrame("Note").slot(Slot.builder("text", DataType.STRING).build()).build());
        f.scripts.define("note-nick", g -> Fixture.call(g, "create", "Note", Map.of("text", "nick set")));
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User");
        e.runToQuiescence();
        f.kb.replace(f.kb.require("u1").withSlot(Fixture.str("nick", "Annie")));
        e.runToQuiescence();
        String note = f.instancesOf("Note").getFirst();
        assertThat(e.why(note).stimuli()).containsExactly("u1");

        assertThat(e.destroy("u1")).containsExactlyInAnyOrder("u1", note);
        assertThat(f.instancesOf("Note")).isEmpty();
    }

    @Test
    void joinChange_twoReferencesAway_isCheckedAgain() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Order", null).cls("Address", null);
        f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mOrder", "Order", ".city == mUser.address.city")).build());
        InferenceEngine e = f.engine();
        f.assertFact("a1", "Address", "city", "Kyoto");
        f.assertFact("u1", "User", "address", "@a1");
        f.assertFact("o1", "Order", "city", "Kyoto");
        e.runToQuiescence();
        assertThat(f.instancesOf("Deliver")).hasSize(1);
        f.kb.replace(f.kb.require("a1").withSlot(Fixture.str("city", "Nara")));
        e.runToQuiescence();
        assertThat(f.instancesOf("Deliver")).isEmpty();
    }

    @Test
    void scriptThatDestroysWhatItRestsOn_thenCreates_leavesNoOrphan_whateverTheOrder() {
        for (boolean destroyFirst : List.of(true, false)) {
            Fixture f = Fixture.paper();
            f.kb.add(Frame.classFrame("Note").slot(Slot.builder("text", DataType.STRING).build()).build());
            f.scripts.define("ask-name", g -> {
                if (destroyFirst) {
                    Fixture.call(g, "destroy", "userA");
                }
                Fixture.call(g, "create", "Note", Map.of("text", "asked"));
                if (!destroyFirst) {
                    Fixture.call(g, "destroy", "userA");
                }
                return null;
            });
            InferenceEngine e = f.engine();
            f.assertFact("mouth1", "Mouth");
            f.assertFact("userA", "NewUser");
            e.runToQuiescence();

            assertThat(f.instancesOf("AskUserName")).isEmpty();
            assertThat(f.instancesOf("Note")).as("the note rests on AskUserName-1, gone with userA (destroy "
                    + (destroyFirst ? "first" : "last") + ")").isEmpty();
        }
    }

    @Test
    void onDestroy_seesTheValuesTheInstanceInheritedFromItsFrame() {
        Fixture f = new Fixture();
        f.cls("User", null);
        f.kb.add(Frame.classFrame("Serve").slot(Fixture.inst("mUser", "User")).slot(Fixture.str("farewell", "bye now"))
                .slot(Fixture.str("onDestroy", "say-farewell")).build());
        List<Object> said = new ArrayList<>();
        f.scripts.define("say-farewell", g -> said.add(Fixture.view(g).get("farewell") + " " + Fixture.view(g).get("mUser")));
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User");
        e.runToQuiescence();

        e.destroy("u1");

        assertThat(said).containsExactly("bye now u1");
    }

    private static List<String> concat(String first, List<String> rest) {
        List<String> out = new ArrayList<>(List.of(first));
        out.addAll(rest);
        return out;
    }

    @Test
    void farPathCondition_whenTheFarInstanceChanges_isCheckedAgainAndReindexed() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("Stim").slot(Slot.builder("key", DataType.INTEGER).build()).build());
        f.kb.add(Frame.classFrame("Target").slot(Slot.builder("key", DataType.INTEGER).build()).build());
        f.kb.add(Frame.classFrame("Holder").slot(Fixture.inst("mS", "Stim")).build());
        f.kb.add(Frame.classFrame("Far").slot(Fixture.inst("mH", "Holder"))
                .slot(Fixture.inst("mT", "Target", ".key == mH.mS.key")).build());
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stim", "key", 1L);
        f.assertFact("t1", "Target", "key", 1L);
        e.runToQuiescence();
        assertThat(f.instancesOf("Far")).hasSize(1);

        f.kb.replace(f.kb.require("s1").withSlot(Fixture.num("key", 2)));
        e.runToQuiescence();
        assertThat(f.instancesOf("Holder")).as("Holder reads s1 directly and has no condition").hasSize(1);
        assertThat(f.instancesOf("Far")).as("Far read s1.key through Holder; 2 != 1 now").isEmpty();
        assertThat(f.traced(TraceEvent.Retracted.class)).anySatisfy(r ->
                assertThat(r.reason()).contains("no longer holds").contains("read through"));

        f.kb.replace(f.kb.require("t1").withSlot(Fixture.num("key", 2)));
        e.runToQuiescence();
        assertThat(f.instancesOf("Far")).as("the index on mH.mS.key was rebuilt with s1's new key").hasSize(1);
    }
}
