package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;

class ExplanationTest {

    @Test
    void why_forThirdStepOfChain_leadsBackThroughEachFiringToTheStimulus() {
        Fixture f = ForwardChainingTest.chain3();
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");
        e.runToQuiescence();
        String step3 = f.instancesOf("Step3").getFirst();

        Explanation why = e.why(step3);

        assertThat(why).isInstanceOfSatisfying(Explanation.Derived.class, d -> {
            assertThat(d.derivation().frame()).isEqualTo("Step3");
            assertThat(d.derivation().binding()).containsEntry("mIn", f.instancesOf("Step2").getFirst());
            assertThat(d.supports()).singleElement().isInstanceOfSatisfying(Explanation.Derived.class, d2 ->
                    assertThat(d2.supports()).singleElement().isInstanceOfSatisfying(Explanation.Derived.class, d1 ->
                            assertThat(d1.supports()).containsExactly(new Explanation.Asserted("s1", "Stimulus"))));
        });
        assertThat(why.stimuli()).containsExactly("s1");
        assertThat(e.why("s1")).isEqualTo(new Explanation.Asserted("s1", "Stimulus"));
    }

    @Test
    void derivation_recordsConditionsWithTheValuesTestedAndTheTriggeringFact() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Order", null);
        f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mOrder", "Order", ".drink == \"tea\"")).build());
        InferenceEngine e = f.engine();
        f.assertFact("o1", "Order", "drink", "tea");
        f.assertFact("u1", "User");
        e.runToQuiescence();
        Derivation d = e.derivation(f.instancesOf("Deliver").getFirst()).orElseThrow();
        assertThat(d.trigger()).isEqualTo("u1");
        assertThat(d.firing()).isEqualTo(1);
        assertThat(d.conditions()).contains(new Derivation.CheckedCondition("mOrder", ".drink == \"tea\"", "tea"),
                new Derivation.CheckedCondition("mUser", "COND_ANY", "u1"));
        assertThat(d.binding().keySet()).as("the binding in the behavior frame's slot order")
                .containsExactly("mUser", "mOrder");
    }

    @Test
    void traceListener_seesAssertMatchActivationFiringScriptAndRetractionInOrder() {
        Fixture f = Fixture.paper();
        InferenceEngine e = f.engine();
        f.assertFact("mouth1", "Mouth");
        f.assertFact("userA", "NewUser");
        e.runToQuiescence();
        e.destroy("userA");
        assertThat(f.trace).extracting(TraceEvent::kind).containsSubsequence("FactAsserted", "FactAsserted",
                "Matched", "Activated", "Fired", "ScriptCalled", "ActionIssued", "ActionChanged", "FactAsserted",
                "Retracted", "FactRemoved");
    }
}
