package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

class BackwardChainingTest {

    @Test
    void ask_whenNothingHasFired_showsWhatCouldBeDerivedWithoutCreatingAnythingOrRunningScripts() {
        Fixture f = ForwardChainingTest.chain3();
        f.kb.replace(f.kb.require("Step1").withSlot(Fixture.str("onInstantiate", "side-effect")));
        f.assertFact("s1", "Stimulus");
        f.assertFact("s2", "Stimulus");
        InferenceEngine e = f.engine();
        long version = f.kb.version();

        List<Answer> answers = e.ask("Step3", Map.of());

        assertThat(answers).hasSize(2).allSatisfy(a -> {
            assertThat(a.derivable()).isTrue();
            assertThat(a.proof().depth()).isEqualTo(3);
        });
        assertThat(answers.stream().map(a -> ((Proof.Derivable) a.proof()).slots().get("mIn"))
                .map(p -> ((Proof.Derivable) p).slots().get("mIn")).map(p -> ((Proof.Derivable) p).slots().get("mIn")))
                .containsExactlyInAnyOrder(new Proof.Exists("s1", "Stimulus"), new Proof.Exists("s2", "Stimulus"));
        assertThat(f.kb.version()).isEqualTo(version);
        assertThat(f.scripts.calls("side-effect")).isZero();
        assertThat(f.instancesOf("Step1")).isEmpty();
    }

    @Test
    void ask_afterForwardChaining_returnsExistingInstancesAndOnlyNewDerivations() {
        Fixture f = ForwardChainingTest.chain3();
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");
        e.runToQuiescence();
        f.kb.add(Frame.instance("s2", "Stimulus").build());

        List<Answer> answers = e.ask("Step1", Map.of());

        assertThat(answers).hasSize(2);
        assertThat(answers.get(0).instance()).isPresent();
        assertThat(answers.get(0).slots()).containsEntry("mIn", "s1");
        assertThat(answers.get(1).derivable()).isTrue();
        assertThat(answers.get(1).slots()).containsEntry("mIn", "s2");
    }

    @Test
    void ask_appliesUniqueAndUnsharedFacetsToRealInstances_asForwardChainingWould() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Mouth", null);
        f.kb.add(Frame.classFrame("OncePerUser").slot(Fixture.inst("mUser", "User"))
                .slot(Slot.builder("mMouth", DataType.INSTANCE).argument("Mouth").required(true).build()).build());
        f.kb.add(Frame.classFrame("TakeMouth").slot(Slot.builder("mMouth", DataType.INSTANCE).argument("Mouth")
                .required(true).shared(false).build())
                .slot(Slot.builder("mUser", DataType.INSTANCE).argument("User").required(true).build()).build());
        InferenceEngine e = f.engine();
        f.assertFact("u1", "User");
        f.assertFact("m1", "Mouth");
        e.runToQuiescence();
        f.kb.add(Frame.instance("u2", "User").build());
        f.kb.add(Frame.instance("m2", "Mouth").build());

        assertThat(e.ask("OncePerUser", Map.of()).stream().filter(Answer::derivable).map(a -> a.slots().get("mUser")))
                .as("u1 already holds the unique key; only u2 can make a new OncePerUser")
                .containsOnly("u2");
        assertThat(e.ask("TakeMouth", Map.of()).stream().filter(Answer::derivable).map(a -> a.slots().get("mMouth")))
                .as("m1 is consumed by the unshared slot of the first TakeMouth")
                .containsOnly("m2");
    }

    @Test
    void ask_withPartialBinding_andConditions_keepsOnlyFittingAnswers() {
        Fixture f = Fixture.paper();
        f.kb.add(Frame.classFrame("Taro").parent("KnownUser").build());
        f.assertFact("mouth1", "Mouth");
        f.assertFact("u1", "Taro");
        f.assertFact("u2", "Taro");
        f.assertFact("n1", "NewUser");
        InferenceEngine e = f.engine();

        assertThat(e.ask("Greeting", Map.of("mUser", Value.ref("u2")))).singleElement()
                .satisfies(a -> assertThat(a.slots()).containsEntry("mUser", "u2").containsEntry("mMouth", "mouth1"));
        assertThat(e.ask("Speech", Map.of())).extracting(Answer::className)
                .containsExactlyInAnyOrder("AskUserName", "Greeting", "Greeting");
        assertThat(e.ask("Greeting", Map.of("mUser", Value.ref("n1")))).isEmpty();
    }

    @Test
    void ask_withABindingNoDerivationWouldHold_derivesNothing_asNoExistingInstanceWouldMatch() {
        Fixture f = Fixture.paper();
        f.assertFact("mouth1", "Mouth");
        f.assertFact("n1", "NewUser");
        InferenceEngine e = f.engine();

        assertThat(e.ask("AskUserName", Map.of("mUser", Value.ref("n1")))).singleElement()
                .satisfies(a -> assertThat(a.slots()).containsEntry("mUser", "n1"));
        assertThat(e.ask("AskUserName", Map.of("mUser", Value.of("n1")))).as("a string, not a reference").isEmpty();
        assertThat(e.ask("AskUserName", Map.of("mUser", Value.ref("mouth1")))).as("not a NewUser").isEmpty();
        assertThat(e.ask("AskUserName", Map.of("mood", Value.of("calm")))).as("a slot AskUserName has not").isEmpty();
        // A slot that is no instance slot: the instance would inherit the class's value.
        assertThat(e.ask("AskUserName", Map.of("onInstantiate", Value.of("ask-name")))).hasSize(1);
        assertThat(e.ask("AskUserName", Map.of("onInstantiate", Value.of("greet")))).isEmpty();
    }

    @Test
    void prove_throughAJoinCondition_testsTheHypotheticalInstanceSlots() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Order", null);
        f.kb.add(Frame.classFrame("Known").slot(Fixture.inst("mUser", "User")).build());
        f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mK", "Known"))
                .slot(Fixture.inst("mOrder", "Order", ".user == mK.mUser")).build());
        f.assertFact("u1", "User");
        f.assertFact("u2", "User");
        f.assertFact("o1", "Order", "user", "@u2");
        InferenceEngine e = f.engine();

        List<Proof> proofs = e.prove("Deliver", Map.of());

        assertThat(proofs).singleElement().isInstanceOfSatisfying(Proof.Derivable.class, p -> {
            assertThat(p.slots().get("mOrder")).isEqualTo(new Proof.Exists("o1", "Order"));
            assertThat(((Proof.Derivable) p.slots().get("mK")).slots()).containsEntry("mUser",
                    new Proof.Exists("u2", "User"));
        });
    }

    @Test
    void ask_runsTheScriptConditionOfABindingOfExistingInstances_andGivesNoAnswerItRejects() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("User").slot(Slot.builder("age", DataType.INTEGER).build()).build());
        f.kb.add(Frame.classFrame("Greet").slot(Fixture.inst("mUser", "User", "js: adult")).build());
        f.scripts.define("adult", g -> ((Number) ((Map<?, ?>) Fixture.view(g).get("mUser")).get("age")).longValue() >= 18);
        f.assertFact("ann", "User", "age", 20L);
        f.assertFact("bob", "User", "age", 12L);
        InferenceEngine e = f.engine(); // matched (ann's binding waits on the agenda), not run
        long version = f.kb.version();
        int matched = f.scripts.calls("adult");

        List<Answer> answers = e.ask("Greet", Map.of());

        assertThat(answers).as("bob's binding is one forward chaining refuses: its script condition is false")
                .singleElement().satisfies(a -> {
                    assertThat(a.slots()).containsEntry("mUser", "ann");
                    assertThat(((Proof.Derivable) a.proof()).assumptions()).as("decided, not assumed").isEmpty();
                });
        assertThat(f.scripts.calls("adult") - matched).as("answered from the outcomes matching kept (each run read "
                + "only its own slot)").isZero();
        assertThat(e.ask("Greet", Map.of("mUser", Value.ref("bob")))).isEmpty();
        assertThat(f.kb.version()).isEqualTo(version);
        assertThat(e.runToQuiescence()).as("what forward chaining then does").isEqualTo(1);
        assertThat(f.instancesOf("Greet")).singleElement()
                .satisfies(g -> assertThat(f.kb.value(g, "mUser")).contains(Value.ref("ann")));
    }

    @Test
    void ask_runsTheScriptConditionsOfAtMostMaxAnswersBindings_andAssumesThoseOfTheRest() {
        Fixture f = new Fixture();
        f.cls("User", null);
        f.kb.add(Frame.classFrame("Greet").slot(Fixture.inst("mUser", "User", "js: never")).build());
        // It reads the whole binding, so no outcome is kept for the instance alone: each binding's is a run.
        f.scripts.define("never", g -> Fixture.view(g).size() < 0);
        for (int i = 1; i <= 5; i++) {
            f.assertFact("u" + i, "User");
        }
        InferenceEngine e = f.engine(EngineOptions.defaults().withMaxAnswers(3));
        int matched = f.scripts.calls("never");

        List<Answer> answers = e.ask("Greet", Map.of());

        assertThat(f.scripts.calls("never") - matched).as("a question runs at most maxAnswers bindings' scripts")
                .isEqualTo(3);
        assertThat(answers).as("the other two are answers only on the assumption that the script holds").hasSize(2)
                .allSatisfy(a -> assertThat(((Proof.Derivable) a.proof()).assumptions())
                        .containsExactly("mUser: js: never"));
        assertThat(e.ask("Greet", Map.of("mUser", Value.ref("u5")))).as("a new question, a new budget").isEmpty();
    }

    @Test
    void ask_assumesTheScriptConditionOfABindingWithAHypotheticalInstance_withoutRunningIt() {
        Fixture f = ForwardChainingTest.chain3();
        f.kb.add(Frame.classFrame("Late").slot(Fixture.inst("mStep", "Step1", "js: never")).build());
        // It reads the whole binding, so no outcome is kept for the instance alone: each binding's is a run.
        f.scripts.define("never", g -> Fixture.view(g).size() < 0);
        f.assertFact("s1", "Stimulus");
        InferenceEngine e = f.engine();

        List<Answer> answers = e.ask("Late", Map.of());

        assertThat(answers).as("Step1 is not made yet: what its instance will hold is not known before it fires")
                .singleElement().satisfies(a -> assertThat(((Proof.Derivable) a.proof()).assumptions())
                        .containsExactly("mStep: js: never"));
        assertThat(f.scripts.calls("never")).isZero();
        e.runToQuiescence();
        assertThat(f.scripts.calls("never")).as("forward chaining runs it once Step1 exists").isEqualTo(1);
        assertThat(e.ask("Late", Map.of())).as("now the binding is of existing instances, and the script says no")
                .isEmpty();
    }

    @Test
    void ask_aScriptConditionThatThrows_rejectsTheBinding_asForwardChainingDoes() {
        Fixture f = new Fixture();
        f.cls("User", null);
        f.kb.add(Frame.classFrame("Greet").slot(Fixture.inst("mUser", "User", "js: broken")).build());
        f.scripts.define("broken", g -> {
            throw new IllegalStateException("s.mUser.profile is undefined");
        });
        f.assertFact("ann", "User");
        InferenceEngine e = f.engine();

        assertThat(e.ask("Greet", Map.of())).isEmpty();
        assertThat(f.traced(TraceEvent.ScriptFailed.class)).isNotEmpty()
                .allSatisfy(t -> assertThat(t.message()).contains("s.mUser.profile is undefined"));
    }

    @Test
    void ask_aBindingThatNeedsOneDerivableInstanceTwice_isNoAnswer_asForwardChainingMakesItOnce() {
        Fixture f = ForwardChainingTest.chain3();
        f.kb.add(Frame.classFrame("Pair").slot(Fixture.inst("mA", "Step1")).slot(Fixture.inst("mB", "Step1")).build());
        f.assertFact("s1", "Stimulus");
        InferenceEngine e = f.engine();

        assertThat(e.ask("Pair", Map.of())).as("s1 gives one Step1 (one binding fires once), and a pair needs two")
                .isEmpty();
        e.runToQuiescence();
        assertThat(f.instancesOf("Pair")).isEmpty();

        f.assertFact("s2", "Stimulus");
        assertThat(e.ask("Pair", Map.of()).stream().filter(Answer::derivable)).as("Step1 of s2 and of s1, both ways")
                .hasSize(2);
        e.runToQuiescence();
        assertThat(f.instancesOf("Pair")).hasSize(2);
    }

    @Test
    void ask_twoDerivableInstancesThatWouldClaimTheSameInstance_areNotBothInOneAnswer() {
        Fixture f = new Fixture();
        f.cls("Tool", null).cls("Job", null);
        f.kb.add(Frame.classFrame("Use").slot(Slot.builder("mTool", DataType.INSTANCE).argument("Tool").required(true)
                .shared(false).build()).slot(Fixture.inst("mJob", "Job")).build());
        f.kb.add(Frame.classFrame("TwoUses").slot(Fixture.inst("mA", "Use")).slot(Fixture.inst("mB", "Use")).build());
        f.assertFact("t1", "Tool");
        f.assertFact("j1", "Job");
        f.assertFact("j2", "Job");
        InferenceEngine e = f.engine();

        assertThat(e.ask("Use", Map.of())).as("each on its own could be made").hasSize(2);
        assertThat(e.ask("TwoUses", Map.of())).as("the unshared slot takes t1 for one Use only").isEmpty();
        e.runToQuiescence();
        assertThat(f.instancesOf("Use")).hasSize(1);
        assertThat(f.instancesOf("TwoUses")).isEmpty();
    }

    @Test
    void ask_twoDerivableInstancesWithTheSameUniqueKey_areNotBothInOneAnswer() {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Mouth", null);
        f.kb.add(Frame.classFrame("Greet").slot(Fixture.inst("mUser", "User")).slot(Slot.builder("mMouth",
                DataType.INSTANCE).argument("Mouth").required(true).build()).build());
        f.kb.add(Frame.classFrame("Twice").slot(Fixture.inst("mA", "Greet")).slot(Fixture.inst("mB", "Greet")).build());
        f.assertFact("u1", "User");
        f.assertFact("m1", "Mouth");
        f.assertFact("m2", "Mouth");
        InferenceEngine e = f.engine();

        assertThat(e.ask("Twice", Map.of())).as("u1 is the unique key of one Greet only").isEmpty();
        e.runToQuiescence();
        assertThat(f.instancesOf("Greet")).hasSize(1);
        assertThat(f.instancesOf("Twice")).isEmpty();
    }

    @Test
    void ask_thatWouldTryMoreCombinationsThanTheLimit_isRefusedInWords_andANarrowerOneIsAnswered() {
        Fixture f = new Fixture();
        f.kb.add(Frame.classFrame("User").slot(Slot.builder("key", DataType.INTEGER).build()).build());
        f.kb.add(Frame.classFrame("Mouth").slot(Slot.builder("key", DataType.INTEGER).build()).build());
        f.kb.add(Frame.classFrame("Match").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mMouth", "Mouth", ".key == mUser.key")).build());
        for (int i = 0; i < 20; i++) {
            f.assertFact("u" + i, "User", "key", (long) i);
            f.assertFact("m" + i, "Mouth", "key", (long) (100 + i)); // no user's key: 400 combinations, no answer
        }
        InferenceEngine e = f.engine(EngineOptions.defaults().withMaxQuestionSteps(100));

        assertThatThrownBy(() -> e.ask("Match", Map.of())).isInstanceOf(QuestionTooBroadException.class)
                .hasMessage("The question about 'Match' is too broad: it tried 100 combinations of instances without "
                        + "finishing (the engine's maxQuestionSteps); hold some of the slots fixed to narrow it.");
        assertThat(e.ask("Match", Map.of("mUser", Value.ref("u3")))).as("20 combinations").isEmpty();
        f.assertFact("m3b", "Mouth", "key", 3L);
        assertThat(e.ask("Match", Map.of("mUser", Value.ref("u3")))).singleElement()
                .satisfies(a -> assertThat(a.slots()).containsEntry("mMouth", "m3b"));
        assertThat(e.runToQuiescence()).as("the engine goes on as before").isEqualTo(1);
    }

    @Test
    void ask_fromScript_returnsAnswersAsPlainMaps() {
        Fixture f = ForwardChainingTest.chain3();
        f.kb.add(Frame.classFrame("Probe").slot(Fixture.inst("mIn", "Step1"))
                .slot(Fixture.str("onInstantiate", "probe")).build());
        Object[] seen = new Object[1];
        f.scripts.define("probe", g -> seen[0] = Fixture.call(g, "ask", "Step3", Map.of()));
        InferenceEngine e = f.engine();
        f.assertFact("s1", "Stimulus");
        e.runToQuiescence();
        assertThat(seen[0]).asInstanceOf(org.assertj.core.api.InstanceOfAssertFactories.LIST).isNotEmpty()
                .allSatisfy(m -> assertThat(((Map<?, ?>) m).keySet()).extracting(Object::toString)
                        .contains("class", "instance", "derivable", "slots"));
    }
}
