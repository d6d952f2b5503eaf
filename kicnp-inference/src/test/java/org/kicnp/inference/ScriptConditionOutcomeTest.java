package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.kicnp.core.ConditionParser;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptRuntime;

/**
 * A script condition whose run reads only its own slot is run once per instance there, not once per binding, and
 * run again when what its outcome rests on changes (real GraalJS; a counting wrapper around the engine's host). The
 * conditions call {@code Number()}, which keeps them out of {@link SimpleCondition}: each decision is a script run.
 */
class ScriptConditionOutcomeTest {
    private static ScriptRuntime runtime;

    @BeforeAll
    static void start() {
        runtime = ScriptRuntime.create(ScriptConfig.defaults().withTimeLimit(Duration.ofMillis(500)));
    }

    @AfterAll
    static void stop() {
        runtime.close();
    }

    /** The real host, counting the script conditions it runs. */
    private static final class Counting implements ScriptHost {
        private final ScriptHost inner = new GraalScriptHost(runtime);
        int conditionRuns;

        @Override public Object run(String frame, String slot, String source, Map<String, Object> globals) {
            return inner.run(frame, slot, source, globals);
        }

        @Override public boolean test(String frame, String slot, String source, Map<String, Object> globals) {
            conditionRuns++;
            return inner.test(frame, slot, source, globals);
        }

        @Override public void prepare(String frame, String slot, String source) {
            // not ahead of time: the count is of runs
        }
    }

    private final Counting host = new Counting();

    /** User(age, name, friend), Mouth(owner), Talk(mUser: User with {@code condition}, mMouth: Mouth). */
    private static KnowledgeBase kb(String condition) {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("User").slot(Slot.builder("age", DataType.INTEGER).build())
                .slot(Slot.builder("name", DataType.STRING).build())
                .slot(Slot.builder("friend", DataType.INSTANCE).argument("User").build()).build());
        kb.add(Frame.classFrame("Mouth").slot(Slot.builder("owner", DataType.STRING).build()).build());
        kb.add(talk(condition));
        return kb;
    }

    private static Frame talk(String condition) {
        return Frame.classFrame("Talk").slot(Slot.builder("mUser", DataType.INSTANCE).argument("User").required(true)
                        .condition(ConditionParser.parse(condition)).build())
                .slot(Slot.builder("mMouth", DataType.INSTANCE).argument("Mouth").required(true).build()).build();
    }

    private static void user(KnowledgeBase kb, String name, int age, String called) {
        kb.put(Frame.instance(name, "User").provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("age", DataType.INTEGER, Value.of(age)))
                .slot(Slot.ofValue("name", DataType.STRING, Value.of(called))).build());
    }

    /** baby (2, Ken), kid (7, Ann), teen (15, Bo). */
    private static void threeUsers(KnowledgeBase kb) {
        user(kb, "baby", 2, "Ken");
        user(kb, "kid", 7, "Ann");
        user(kb, "teen", 15, "Bo");
    }

    private static void mouth(KnowledgeBase kb, String name, String owner) {
        kb.add(Frame.instance(name, "Mouth").provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("owner", DataType.STRING, Value.of(owner))).build());
    }

    /** The (user, mouth) of every Talk instance, sorted. */
    private static List<String> talks(KnowledgeBase kb) {
        List<String> out = new ArrayList<>();
        for (Frame t : kb.instancesOf("Talk")) {
            out.add(kb.value(t.name(), "mUser").orElseThrow().text() + "+" + kb.value(t.name(), "mMouth").orElseThrow()
                    .text());
        }
        return out.stream().sorted().toList();
    }

    @Test
    void aConditionReadingOnlyItsOwnSlot_runsOncePerInstance_notOncePerBinding() {
        KnowledgeBase kb = kb("js: Number(s.mUser.age) > 3");
        try (InferenceEngine e = InferenceEngine.builder(kb).scripts(host).build()) {
            threeUsers(kb);
            mouth(kb, "m1", "Ann");
            e.runToQuiescence();
            assertThat(host.conditionRuns).isEqualTo(3);

            mouth(kb, "m2", "Bo");
            mouth(kb, "m3", "Ken");
            e.runToQuiescence();

            assertThat(talks(kb)).containsExactly("kid+m1", "kid+m2", "kid+m3", "teen+m1", "teen+m2", "teen+m3");
            assertThat(host.conditionRuns).as("the six new bindings answered from the three outcomes kept")
                    .isEqualTo(3);
        }
    }

    @Test
    void aSimpleCondition_isDecidedWithoutRunningTheScript_andKeptAsAScriptsOutcomeIs() {
        KnowledgeBase kb = kb("js: s.mUser.age > 3 && s.mUser.name != 'Bo'");
        try (InferenceEngine e = InferenceEngine.builder(kb).scripts(host).build()) {
            threeUsers(kb);
            mouth(kb, "m1", "Ann");
            mouth(kb, "m2", "Bo");
            e.runToQuiescence();

            assertThat(talks(kb)).containsExactly("kid+m1", "kid+m2");
            assertThat(host.conditionRuns).as("no GraalJS run").isZero();
            user(kb, "kid", 2, "Ann");
            e.runToQuiescence();
            assertThat(talks(kb)).as("decided again after the change, and retracted").isEmpty();
        }
    }

    @Test
    void aConditionReadingAnotherSlot_runsForEachBindingThatReadsIt_andDecidesEachPairItself() {
        // baby's run stops at its age, having read mUser only: kept. The others read mMouth too: run per pair.
        KnowledgeBase kb = kb("js: Number(s.mUser.age) > 3 && s.mMouth.owner == s.mUser.name");
        try (InferenceEngine e = InferenceEngine.builder(kb).scripts(host).build()) {
            threeUsers(kb);
            mouth(kb, "m1", "Ann");
            mouth(kb, "m2", "Bo");
            mouth(kb, "m3", "Ann");
            e.runToQuiescence();

            assertThat(talks(kb)).containsExactly("kid+m1", "kid+m3", "teen+m2");
            assertThat(host.conditionRuns).as("baby once, kid and teen once per mouth").isEqualTo(1 + 2 * 3);
        }
    }

    @Test
    void whenTheInstanceChanges_itsConditionRunsAgain_andWhatRestedOnTheOldOutcomeFollows() {
        KnowledgeBase kb = kb("js: Number(s.mUser.age) > 3");
        try (InferenceEngine e = InferenceEngine.builder(kb).scripts(host).build()) {
            user(kb, "baby", 2, "Ken");
            mouth(kb, "m1", "Ann");
            e.runToQuiescence();
            assertThat(talks(kb)).isEmpty();

            user(kb, "baby", 5, "Ken"); // a birthday or three
            e.runToQuiescence();
            assertThat(talks(kb)).containsExactly("baby+m1");
            int afterChange = host.conditionRuns;
            assertThat(afterChange).isEqualTo(2);

            mouth(kb, "m2", "Bo");
            e.runToQuiescence();
            assertThat(talks(kb)).containsExactly("baby+m1", "baby+m2");
            assertThat(host.conditionRuns).as("the new outcome kept").isEqualTo(afterChange);

            user(kb, "baby", 1, "Ken");
            e.runToQuiescence();
            assertThat(talks(kb)).as("retracted: the condition runs again and is false").isEmpty();
            assertThat(host.conditionRuns).isGreaterThan(afterChange);
        }
    }

    @Test
    void whenAnInstanceReadThroughTheSlotChanges_theConditionRunsAgain() {
        KnowledgeBase kb = kb("js: Number(s.mUser.friend.age) > 3");
        try (InferenceEngine e = InferenceEngine.builder(kb).scripts(host).build()) {
            user(kb, "pal", 2, "Pal");
            kb.add(Frame.instance("u", "User").provenance(Provenance.RUNTIME)
                    .slot(Slot.ofValue("friend", DataType.INSTANCE, Value.ref("pal"))).build());
            mouth(kb, "m1", "Ann");
            e.runToQuiescence();
            assertThat(talks(kb)).isEmpty();

            user(kb, "pal", 9, "Pal"); // changes what u's condition reads through u
            e.runToQuiescence();

            assertThat(talks(kb)).containsExactly("u+m1");
        }
    }

    @Test
    void whenTheFrameIsEdited_itsConditionRunsAgain() {
        KnowledgeBase kb = kb("js: Number(s.mUser.age) > 3");
        try (InferenceEngine e = InferenceEngine.builder(kb).scripts(host).build()) {
            user(kb, "kid", 7, "Ann");
            mouth(kb, "m1", "Ann");
            e.runToQuiescence();
            assertThat(talks(kb)).containsExactly("kid+m1");

            kb.replace(talk("js: Number(s.mUser.age) > 8"));
            mouth(kb, "m2", "Bo");
            e.runToQuiescence();

            assertThat(talks(kb)).as("kid is 7: the edited condition is false for it").isEmpty();
        }
    }
}
