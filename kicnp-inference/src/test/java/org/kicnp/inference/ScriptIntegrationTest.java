package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptRuntime;

/** The engine with the real GraalJS runtime and the paper's frames as XML. */
class ScriptIntegrationTest {
    private static final Path TABLE5 = Path.of("..", "scenarios", "table5");
    private static ScriptRuntime runtime;

    @BeforeAll
    static void start() {
        runtime = ScriptRuntime.create(ScriptConfig.defaults().withTimeLimit(Duration.ofMillis(500)));
    }

    @AfterAll
    static void stop() {
        runtime.close();
    }

    private final List<Action> sent = new ArrayList<>();
    private final List<TraceEvent> trace = new ArrayList<>();

    private InferenceEngine engine(KnowledgeBase kb) {
        InferenceEngine e = InferenceEngine.builder(kb).scripts(new GraalScriptHost(runtime)).actionSink(sent::add)
                .build();
        e.addTraceListener(trace::add);
        return e;
    }

    private static KnowledgeBase paper() {
        KnowledgeBase kb = KnowledgeBase.create();
        KnowledgeLoader.load(kb, List.of(TABLE5));
        return kb;
    }

    private static void fact(KnowledgeBase kb, String name, String cls, Slot... slots) {
        Frame.Builder b = Frame.instance(name, cls).provenance(Provenance.RUNTIME);
        for (Slot s : slots) {
            b.slot(s);
        }
        kb.add(b.build());
    }

    @Test
    void paperScenario_newUserAndMouth_askTheName_knownUserIsGreetedWithThePaperScript() {
        KnowledgeBase kb = paper();
        InferenceEngine e = engine(kb);
        fact(kb, "userA", "NewUser");
        e.runToQuiescence();
        // hierarchy.xml gives Mouth a required robot slot, so Mouth is itself a behavior frame (section 4.4: "Mouth"
        // is activated when a robot connects) and each robot gets a Mouth; RobovieMouth is the declared one.
        assertThat(kb.instancesOf("AskUserName")).filteredOn(f -> kb.value(f.name(), "mMouth")
                .equals(java.util.Optional.of(Value.ref("RobovieMouth")))).hasSize(1);
        assertThat(sent).anySatisfy(a -> {
            assertThat(a.target()).isEqualTo("RobovieMouth");
            assertThat(a.robot()).isEqualTo("Robovie");
            assertThat(a.name()).isEqualTo("say");
            assertThat(a.args()).containsExactly("How are you! I have never seen you before. What is your name?");
        });

        kb.add(Frame.classFrame("Taro").parent("KnownUser").provenance(Provenance.LEARNED).build());
        fact(kb, "userB", "Taro");
        e.runToQuiescence();
        assertThat(kb.instancesOf("Greeting")).isNotEmpty().allSatisfy(g ->
                assertThat(kb.value(g.name(), "mUser")).contains(Value.ref("userB")));
        assertThat(sent).anySatisfy(a ->
                assertThat(a.args()).containsExactly("Hi! Nice to meet you. Welcome to visit my room!"));
    }

    private static KnowledgeBase small(String onInstantiate, String condition) {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("User").slot(Slot.builder("age", DataType.INTEGER).build())
                .slot(Slot.builder("name", DataType.STRING).build()).build());
        kb.add(Frame.classFrame("Mouth").build());
        kb.add(Frame.classFrame("KnownUser").parent("User").build());
        Slot.Builder user = Slot.builder("mUser", DataType.INSTANCE).argument("User").required(true);
        if (condition != null) {
            user.condition(org.kicnp.core.ConditionParser.parse(condition));
        }
        kb.add(Frame.classFrame("Talk").slot(user.build())
                .slot(Slot.builder("mMouth", DataType.INSTANCE).argument("Mouth").required(true).build())
                .slot(Slot.ofValue("onInstantiate", DataType.STRING, Value.of(onInstantiate))).build());
        kb.add(Frame.instance("m1", "Mouth").build());
        return kb;
    }

    @Test
    void engineStart_preparesEveryRulesScripts_inTheBackground_underTheIdsTheirRunsUse() throws Exception {
        KnowledgeBase kb = small("sendmsg(s.mMouth, 'hello ' + s.mUser.name)", "js: s.mUser.age > 3");
        kb.replace(kb.require("Talk").withSlot(Slot.ofValue("onDestroy", DataType.STRING, Value.of("log('bye')"))));
        kb.add(Frame.classFrame("Shout").parent("Talk").build()); // inherits the scripts: prepared under its own name
        java.util.concurrent.LinkedBlockingQueue<String> prepared = new java.util.concurrent.LinkedBlockingQueue<>();
        ScriptHost recording = new ScriptHost() {
            @Override public Object run(String frame, String slot, String source, Map<String, Object> globals) {
                return null;
            }

            @Override public boolean test(String frame, String slot, String source, Map<String, Object> globals) {
                return true;
            }

            @Override public void prepare(String frame, String slot, String source) {
                prepared.add(frame + "." + slot + ": " + source);
            }
        };

        try (InferenceEngine e = InferenceEngine.builder(kb).scripts(recording).build()) {
            List<String> seen = new ArrayList<>();
            for (int i = 0; i < 6; i++) {
                seen.add(prepared.poll(10, java.util.concurrent.TimeUnit.SECONDS));
            }
            assertThat(seen).containsExactlyInAnyOrder(
                    "Talk.onInstantiate: sendmsg(s.mMouth, 'hello ' + s.mUser.name)", "Talk.onDestroy: log('bye')",
                    "Talk.mUser: s.mUser.age > 3",
                    "Shout.onInstantiate: sendmsg(s.mMouth, 'hello ' + s.mUser.name)", "Shout.onDestroy: log('bye')",
                    "Shout.mUser: s.mUser.age > 3");
        }
    }

    @Test
    void graalHostPrepare_ofAScriptThatDoesNotParse_leavesItToItsRun() {
        GraalScriptHost host = new GraalScriptHost(runtime);

        host.prepare("Talk", "onInstantiate", "sendmsg(");

        assertThatThrownBy(() -> host.run("Talk", "onInstantiate", "sendmsg(", Map.of()))
                .hasMessageContaining("Talk");
    }

    @Test
    void scriptCondition_seesTheBindingAsS() {
        KnowledgeBase kb = small("sendmsg(s.mMouth, 'hello ' + s.mUser.name)", "js: s.mUser.age > 3");
        InferenceEngine e = engine(kb);
        fact(kb, "baby", "User", Slot.ofValue("age", DataType.INTEGER, Value.of(2)),
                Slot.ofValue("name", DataType.STRING, Value.of("Ken")));
        fact(kb, "kid", "User", Slot.ofValue("age", DataType.INTEGER, Value.of(7)),
                Slot.ofValue("name", DataType.STRING, Value.of("Ann")));
        e.runToQuiescence();
        assertThat(sent).singleElement().satisfies(a -> {
            assertThat(a.robot()).isEqualTo("m1");
            assertThat(a.args()).containsExactly("hello Ann");
        });
    }

    @Test
    void ask_runsTheScriptConditionOfABindingOfExistingInstances_fromJavaAndFromAScriptRunningInTheEngine() {
        KnowledgeBase kb = small("log('talking to', s.mUser.name)", "js: s.mUser.age > 3");
        kb.add(Frame.classFrame("Trigger").build());
        kb.add(Frame.classFrame("Probe").slot(Slot.builder("mT", DataType.INSTANCE).argument("Trigger").required(true)
                .build()).slot(Slot.ofValue("onInstantiate", DataType.STRING, Value.of(
                        "sendmsg('m1', ask('Talk', {}).map(a => a.slots.mUser).join(','))"))).build());
        InferenceEngine e = engine(kb);
        fact(kb, "baby", "User", Slot.ofValue("age", DataType.INTEGER, Value.of(2)));
        fact(kb, "kid", "User", Slot.ofValue("age", DataType.INTEGER, Value.of(7)));

        assertThat(e.ask("Talk", Map.of())).as("baby is too young: the condition's script says so").singleElement()
                .satisfies(a -> {
                    assertThat(a.slots()).containsEntry("mUser", "kid");
                    assertThat(((Proof.Derivable) a.proof()).assumptions()).isEmpty();
                });

        fact(kb, "t1", "Trigger");
        e.runToQuiescence();
        // Whether Talk fired before Probe or after, kid answers (derivable, or made) and baby does not.
        assertThat(sent).filteredOn(a -> a.name().equals("say")).singleElement()
                .satisfies(a -> assertThat(a.args()).containsExactly("kid"));
        assertThat(trace).noneMatch(t -> t instanceof TraceEvent.ScriptFailed);
    }

    @Test
    void ask_fromAScript_tooBroadForTheEnginesLimit_failsThatScript_inTheLimitsWords() {
        KnowledgeBase kb = small("log('talking to', s.mUser.name)", null);
        kb.add(Frame.classFrame("Trigger").build());
        kb.add(Frame.classFrame("Probe").slot(Slot.builder("mT", DataType.INSTANCE).argument("Trigger").required(true)
                .build()).slot(Slot.ofValue("onInstantiate", DataType.STRING, Value.of(
                        "sendmsg('m1', 'answers: ' + ask('Talk', {}).length)"))).build());
        for (int i = 0; i < 3; i++) {
            kb.add(Frame.instance("m" + (i + 2), "Mouth").build());
            fact(kb, "u" + i, "User");
        }
        try (InferenceEngine e = InferenceEngine.builder(kb).scripts(new GraalScriptHost(runtime)).actionSink(sent::add)
                .options(EngineOptions.defaults().withMaxQuestionSteps(5)).build()) {
            e.addTraceListener(trace::add);
            fact(kb, "t1", "Trigger");
            e.runToQuiescence();

            assertThat(sent).noneMatch(a -> a.args().toString().contains("answers"));
            assertThat(trace).filteredOn(t -> t instanceof TraceEvent.ScriptFailed).singleElement()
                    .satisfies(t -> assertThat(((TraceEvent.ScriptFailed) t).message())
                            .contains("The question about 'Talk' is too broad: it tried 5 combinations"));
        }
    }

    @Test
    void scriptApi_createLearnCommandAndLog_takeEffectAfterTheScriptSucceeds() {
        KnowledgeBase kb = small("""
                log('registering', s.mUser.name);
                learn(s.mUser.name + 'User', 'KnownUser', {heard: s.mUser.name});
                const id = command('PINO', 'shake_hands', ['both']);
                create('Note', {text: 'hi'});
                """, null);
        kb.add(Frame.classFrame("Note").slot(Slot.builder("text", DataType.STRING).build()).build());
        InferenceEngine e = engine(kb);
        fact(kb, "u1", "User", Slot.ofValue("name", DataType.STRING, Value.of("Taro")));
        e.runToQuiescence();
        assertThat(kb.require("TaroUser").provenance()).isEqualTo(Provenance.LEARNED);
        assertThat(kb.require("TaroUser").parent()).contains("KnownUser");
        assertThat(kb.value("TaroUser", "heard")).contains(Value.of("Taro"));
        assertThat(sent).singleElement().satisfies(a -> {
            assertThat(a.name()).isEqualTo("shake_hands");
            assertThat(a.args()).containsExactly("both");
        });
        assertThat(kb.instancesOf("Note")).singleElement()
                .satisfies(n -> assertThat(kb.value(n.name(), "text")).contains(Value.of("hi")));
    }

    @Test
    void learn_neverOverwritesADeclaredFrame() {
        KnowledgeBase kb = small("learn('Mouth', 'KnownUser', {})", null);
        InferenceEngine e = engine(kb);
        fact(kb, "u1", "User");
        e.runToQuiescence();
        assertThat(kb.require("Mouth").parent()).isEmpty();
        assertThat(trace).filteredOn(t -> t instanceof TraceEvent.ScriptFailed).singleElement()
                .satisfies(t -> assertThat(((TraceEvent.ScriptFailed) t).message())
                        .isEqualTo("learn() cannot replace frame 'Mouth': it was not learned."));
    }

    @Test
    void frameExists_letsAScriptLearnUnderAFreeName_besideADeclaredFrameOfThatName() {
        KnowledgeBase kb = small("""
                var cls = 'Mouth';
                for (var n = 2; frameExists(cls); n++) { cls = 'Mouth_' + n; }
                learn(cls, 'KnownUser', {name: 'Mouth', checked: String(frameExists('Mouth')) + String(frameExists('Nobody'))});
                """, null);
        InferenceEngine e = engine(kb);
        fact(kb, "u1", "User");
        e.runToQuiescence();
        assertThat(kb.require("Mouth").learned()).isFalse();
        assertThat(kb.require("Mouth_2").parent()).contains("KnownUser");
        assertThat(kb.value("Mouth_2", "name")).contains(Value.of("Mouth"));
        assertThat(kb.value("Mouth_2", "checked")).contains(Value.of("truefalse"));
        assertThat(trace).noneMatch(t -> t instanceof TraceEvent.ScriptFailed);
    }

    @Test
    void endlessLoop_isStoppedByTheTimeBound_andTheEngineCarriesOn() {
        KnowledgeBase kb = small("sendmsg(s.mMouth, 'before'); while (true) {}", null);
        InferenceEngine e = engine(kb);
        fact(kb, "u1", "User");
        e.runToQuiescence();
        assertThat(sent).isEmpty();
        assertThat(kb.instancesOf("Talk")).isEmpty();
        assertThat(trace).filteredOn(t -> t instanceof TraceEvent.ScriptFailed).singleElement()
                .satisfies(t -> assertThat(((TraceEvent.ScriptFailed) t).message()).contains("onInstantiate")
                        .contains("Talk"));
        kb.replace(kb.require("Talk").withSlot(Slot.ofValue("onInstantiate", DataType.STRING, Value.of("1"))));
        fact(kb, "u2", "User");
        e.runToQuiescence();
        assertThat(kb.instancesOf("Talk")).hasSize(1);
    }

    @Test
    void syntaxError_failsTheFiringWithAMessageNamingFrameAndSlot() {
        KnowledgeBase kb = small("sendmsg(s.mMouth, 'unclosed);", null);
        InferenceEngine e = engine(kb);
        fact(kb, "u1", "User");
        e.runToQuiescence();
        assertThat(kb.instancesOf("Talk")).isEmpty();
        assertThat(trace).filteredOn(t -> t instanceof TraceEvent.ScriptFailed).singleElement()
                .satisfies(t -> assertThat(((TraceEvent.ScriptFailed) t).message())
                        .contains("'onInstantiate'").contains("'Talk'"));
    }

    @Test
    void demons_onNeededComputesMissingValue_onAddedAndOnRemovedRunWhenSlotChanges() {
        KnowledgeBase kb = small("1", null);
        kb.replace(kb.require("User").withSlot(Slot.builder("nick", DataType.STRING)
                .onNeeded("'nick-' + s.name").onAdded("sendmsg('log', 'added ' + s.nick)")
                .onRemoved("sendmsg('log', 'removed')").reactive(false).build()));
        kb.replace(kb.require("User").withSlot(Slot.builder("mood", DataType.STRING).onNeeded("void 0").build()));
        InferenceEngine e = engine(kb);
        fact(kb, "u1", "User", Slot.ofValue("name", DataType.STRING, Value.of("Ann")));
        e.runToQuiescence();
        assertThat(e.read("u1", "nick")).contains(Value.of("nick-Ann"));
        assertThat(e.read("u1", "name")).contains(Value.of("Ann"));
        assertThat(e.read("u1", "age")).isEmpty();
        assertThat(e.read("u1", "mood")).isEmpty();
        int fired = trace.stream().filter(t -> t instanceof TraceEvent.Fired).toList().size();

        kb.replace(kb.require("u1").withSlot(Slot.ofValue("nick", DataType.STRING, Value.of("A"))));
        e.runToQuiescence();
        kb.replace(kb.require("u1").toBuilder().removeSlot("nick").build());
        e.runToQuiescence();

        assertThat(sent).extracting(a -> a.args().getFirst()).containsExactly("added A", "removed");
        assertThat(trace).filteredOn(t -> t instanceof TraceEvent.FactChanged).isEmpty();
        assertThat(trace.stream().filter(t -> t instanceof TraceEvent.Fired).toList()).hasSize(fired);
    }

    @Test
    void reactiveSlot_whenChanged_isMatchedAgain() {
        KnowledgeBase kb = small("1", ".age >= 18");
        InferenceEngine e = engine(kb);
        fact(kb, "u1", "User", Slot.ofValue("age", DataType.INTEGER, Value.of(17)));
        e.runToQuiescence();
        assertThat(kb.instancesOf("Talk")).isEmpty();
        kb.replace(kb.require("u1").withSlot(Slot.ofValue("age", DataType.INTEGER, Value.of(18))));
        e.runToQuiescence();
        assertThat(kb.instancesOf("Talk")).hasSize(1);
        assertThat(e.ask("Talk", Map.of())).hasSize(1);
    }
}
