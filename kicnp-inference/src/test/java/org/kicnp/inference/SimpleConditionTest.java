package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptRuntime;

/**
 * {@link SimpleCondition} against GraalJS: every condition below, for every instance below, either is left to the
 * script or gives what the script gives (the real runtime, with the same {@code s}).
 */
class SimpleConditionTest {
    private static ScriptRuntime runtime;
    private static GraalScriptHost host;

    @BeforeAll
    static void start() {
        runtime = ScriptRuntime.create(ScriptConfig.defaults().withTimeLimit(Duration.ofSeconds(5)));
        host = new GraalScriptHost(runtime);
    }

    @AfterAll
    static void stop() {
        runtime.close();
    }

    /** Conditions that must be decided without the script, for every instance below. */
    private static final List<String> DECIDED = List.of(
            "(s.mDone.frame == \"Greeting\") && s.mDone.status == \"ended\"",
            "(s.mDone.frame == \"ScoutServesCup\" || s.mDone.frame == \"DrinkOrder\" || s.mDone.frame == \"Greeting\")"
                    + " && s.mDone.status == \"ended\"",
            "s.mDone.frame == 'Greeting';",
            "s.mDone.frame != \"Greeting\"",
            "s.mDone.frame === \"Greeting\" || s.mDone.frame !== \"AskDrink\"",
            "s.mDone.missing == null", "s.mDone.missing != null", "s.mDone.missing === null",
            "!s.mDone.missing", "!s.mDone.flag", "!!s.mDone.frame", "!s.mDone.empty", "!s.mDone.other",
            "!s.mDone.items", "!s.mDone", "!s.mUser", "!(s.mDone.frame == \"Greeting\" && !s.mDone.flag)",
            "true", "false", "true && !false", "s.mDone.$name == \"t1\"", "s.mDone.$class == 'Feedback'",
            "(s.mDone.frame == \"Greeting\") &&s.mDone.status==\"ended\"", "\n  s.mDone.frame == \"Greeting\"\n");

    /** Conditions decided for every instance whose slots they compare have values (all but t4). */
    private static final List<String> WHEN_SET = List.of(
            "s.mDone.frame < \"B\"", "s.mDone.frame >= \"Greeting\"", "s.mDone.status <= 'ended'",
            "s.mDone.status < 'ended'", "s.mDone.frame > \"a\"",
            "s.mDone.n > 2", "s.mDone.n >= 3", "s.mDone.n < 3.5", "s.mDone.n == 3", "s.mDone.n === 3",
            "s.mDone.r == 3", "s.mDone.n != 0", "s.mDone.r > 0", "s.mDone.r === 0", "s.mDone.r < 0", "!s.mDone.n",
            "!s.mDone.r", "s.mDone.flag == true", "s.mDone.flag === false", "s.mDone.flag != false",
            "s.mDone.n <= 0.5 || s.mDone.r >= 2.5");

    /** Conditions that may or may not be decided, depending on the values (a conversion, an object, a throw). */
    private static final List<String> MAYBE = List.of(
            "s.mDone.n == \"3\"", "s.mDone.flag == 1", "s.mDone.other == \"t2\"", "s.mDone.other === s.mDone.other",
            "s.mDone.frame.length > 3", "s.mUser.name == \"x\"", "s.mDone.toString == null",
            "s.mDone.__proto__ == null", "s.mDone.missing.deeper == 1", "s.mDone.frame < 3", "s.mDone.n < \"4\"",
            "s.mDone.other.frame == \"AskDrink\"", "!s.mDone.other.flag");

    /**
     * Chains of {@code &&} whose first terms are simple and a later one is not: decided (false) where a simple term is
     * false, else left to the script (Table 5's first two; a text or regular expression holding "&&" is not a split).
     */
    private static final List<String> CHAINS = List.of(
            "s.mDone.robot == \"Scout\" && s.mDone.status != \"ended\" && "
                    + "!/retracted|predecessor|cancelled: the order changed/.test(String(s.mDone.result))",
            "s.mDone.frame == \"AIBOAction1\" && s.mDone.status != \"ended\" && !/retracted/.test(String(s.mDone.result))",
            "s.mDone.frame == \"Greeting\" && String(s.mDone.status).length > 2",
            "s.mDone.frame == \"a && b\" && Number(s.mDone.n) > 1", "s.mDone.n > 1 && /a&&b/.test(s.mDone.frame)",
            "!s.mDone.flag && s.mDone.frame.indexOf('e') >= 0", "s.mDone.frame == 'Greeting' && (s.mDone.n = 1);",
            "s.mDone.status == 'ended' && s.mDone.n / 2 > 1 && s.mDone.r / 2 > 1",
            "s.mDone.frame == 'x' && (() => true)()"); // an arrow inside brackets binds nothing at the top

    /** Texts that are not one of the simple forms: they run as scripts. */
    private static final List<String> NOT_SIMPLE = List.of(
            "s.mDone.flag", "s.mDone.frame", "s.mDone.frame.startsWith(\"G\")", "/x/.test(s.mDone.frame)",
            "s.mDone.n + 1 > 3", "s.mDone.n > 1e0", "s.mDone.n > 0x1", "s.mDone.frame == \"a\\\"b\"",
            "s.mDone['frame'] == 'x'", "undefined == s.mDone.missing", "String(s.mDone.result) == 'x'",
            "s.mDone.frame == \"G\" & s.mDone.n > 1", "s.mDone.n > 1 ? true : false", "s == null", "s.mDone.n > -1",
            "(s.mDone.frame) == \"Greeting\"", "s.mDone.frame == \"G\"; s.mDone.n > 1", "// c\ntrue", "a.b == 1",
            "s.mDone.n > 012", "s.mDone.n > 1.", "s.mDone.n > .5",
            // && chains that cannot be split with certainty: a lower operator at the top, braces, a template, a comment
            "s.mDone.frame == \"Greeting\" && Number(s.mDone.n) > 1 || true",
            "s.mDone.frame == \"Greeting\" && Number(s.mDone.n) > 1 ? false : true",
            "s.mDone.frame == \"Greeting\" && Number(s.mDone.n) > 1, true",
            "s.mDone.frame == 'x' && {a: 1}.a", "s.mDone.frame == 'x' && `${s.mDone.n}` == '3'",
            "s.mDone.frame == 'x' && f(1) // note", "s.mDone.frame == 'x' && g(\"unclosed)",
            "s.mDone.frame == 'x' && x = 1", "s.mDone.frame == 'x' && y ?? z");

    private static KnowledgeBase kb() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("Feedback")
                .slot(Slot.builder("frame", DataType.STRING).build())
                .slot(Slot.builder("status", DataType.STRING).build())
                .slot(Slot.builder("robot", DataType.STRING).build())
                .slot(Slot.builder("result", DataType.STRING).build())
                .slot(Slot.builder("empty", DataType.STRING).build())
                .slot(Slot.builder("n", DataType.INTEGER).build())
                .slot(Slot.builder("r", DataType.FLOAT).build())
                .slot(Slot.builder("flag", DataType.BOOLEAN).build())
                .slot(Slot.builder("items", DataType.LIST).build())
                .slot(Slot.builder("other", DataType.INSTANCE).argument("Feedback").build()).build());
        kb.add(Frame.instance("t2", "Feedback").slot(str("frame", "AskDrink")).slot(str("status", "started"))
                .slot(Slot.ofValue("n", DataType.INTEGER, Value.of(0)))
                .slot(Slot.ofValue("r", DataType.FLOAT, Value.of(-0.0)))
                .slot(Slot.ofValue("flag", DataType.BOOLEAN, Value.of(false))).build());
        kb.add(Frame.instance("t1", "Feedback").slot(str("frame", "Greeting")).slot(str("status", "ended"))
                .slot(str("empty", "")).slot(Slot.ofValue("n", DataType.INTEGER, Value.of(3)))
                .slot(Slot.ofValue("r", DataType.FLOAT, Value.of(3.0)))
                .slot(Slot.ofValue("flag", DataType.BOOLEAN, Value.of(true)))
                .slot(Slot.ofValue("items", DataType.LIST, new Value.Lst(List.of(Value.of("a"), Value.of("b")))))
                .slot(Slot.ofValue("other", DataType.INSTANCE, Value.ref("t2"))).build());
        kb.add(Frame.instance("t3", "Feedback").slot(str("frame", "Áé Greeting")).slot(str("status", "endeD"))
                .slot(str("robot", "Scout")).slot(str("result", "retracted: the order changed"))
                .slot(Slot.ofValue("n", DataType.INTEGER, Value.of(-7)))
                .slot(Slot.ofValue("r", DataType.FLOAT, Value.of(2.5))).build());
        kb.add(Frame.instance("t4", "Feedback").build()); // every slot empty
        return kb;
    }

    private static Slot str(String name, String value) {
        return Slot.ofValue(name, DataType.STRING, Value.of(value));
    }

    /** What the native evaluation gives (empty: left to the script), and what GraalJS gives (or its error). */
    private record Outcome(String condition, String instance, Optional<Boolean> nativeAnswer, Object script) {
    }

    private static Outcome both(KnowledgeBase kb, String condition, String instance) {
        Map<String, String> binding = new LinkedHashMap<>();
        binding.put("mDone", instance);
        Optional<Boolean> nativeAnswer = SimpleCondition.parse(condition)
                .flatMap(c -> c.test(new ConditionView(kb, binding, "mDone")));
        Object script;
        try {
            script = host.test("Row", "mDone", condition, Map.of("s", new ConditionView(kb, binding, "mDone")));
        } catch (RuntimeException e) {
            script = e.getClass().getSimpleName();
        }
        return new Outcome(condition, instance, nativeAnswer, script);
    }

    @Test
    void everySimpleCondition_givesWhatGraalJsGives_orLeavesItToTheScript() {
        KnowledgeBase kb = kb();
        List<String> all = new ArrayList<>(DECIDED);
        all.addAll(WHEN_SET);
        all.addAll(MAYBE);
        all.addAll(CHAINS);
        List<Outcome> decided = new ArrayList<>();
        for (String condition : all) {
            assertThat(SimpleCondition.parse(condition)).as("'%s' is one of the simple forms", condition).isPresent();
            for (String instance : List.of("t1", "t2", "t3", "t4")) {
                Outcome o = both(kb, condition, instance);
                if (o.nativeAnswer().isPresent()) {
                    assertThat(o.script()).as("'%s' for %s", condition, instance).isEqualTo(o.nativeAnswer().get());
                    decided.add(o);
                }
                if (DECIDED.contains(condition) || WHEN_SET.contains(condition) && !instance.equals("t4")) {
                    assertThat(o.nativeAnswer()).as("'%s' for %s is decided without the script", condition, instance)
                            .isPresent();
                }
            }
        }
        // Both answers occur, so the comparison above could fail either way.
        assertThat(decided).anyMatch(o -> o.nativeAnswer().get()).anyMatch(o -> !o.nativeAnswer().get());
    }

    @Test
    void conditionsThatMeetAConversionAnObjectOrAThrow_areLeftToTheScript() {
        KnowledgeBase kb = kb();
        assertThat(both(kb, "s.mDone.n == \"3\"", "t1").nativeAnswer()).isEmpty();
        assertThat(both(kb, "s.mDone.other == \"t2\"", "t1").nativeAnswer()).isEmpty();
        assertThat(both(kb, "s.mDone.frame.length > 3", "t1").nativeAnswer()).isEmpty();
        assertThat(both(kb, "s.mDone.toString == null", "t1").nativeAnswer()).isEmpty();
        Outcome unbound = both(kb, "s.mUser.name == \"x\"", "t1");
        assertThat(unbound.nativeAnswer()).isEmpty();
        assertThat(unbound.script()).as("JavaScript throws: s.mUser is undefined").isInstanceOf(String.class);
        // Short-circuit as JavaScript: a false left side decides before the right side's conversion is met.
        assertThat(both(kb, "s.mDone.frame == \"Nope\" && s.mDone.n == \"3\"", "t1").nativeAnswer()).contains(false);
    }

    @Test
    void aChainsSimpleFirstTerms_decideItWhenOneIsFalse_andLeaveTheRestToTheScript() {
        KnowledgeBase kb = kb();
        String scout = CHAINS.getFirst();
        assertThat(both(kb, scout, "t1").nativeAnswer()).as("t1 is no robot's: decided false").contains(false);
        Outcome t3 = both(kb, scout, "t3");
        assertThat(t3.nativeAnswer()).as("Scout's, not ended: the regular expression decides").isEmpty();
        assertThat(t3.script()).isEqualTo(false);
        Outcome split = both(kb, "s.mDone.frame == \"a && b\" && Number(s.mDone.n) > 1", "t1");
        assertThat(split.nativeAnswer()).contains(false);
        assertThat(split.script()).isEqualTo(false);
        // JavaScript reads (false && x) || true as true: a chain with '||' at the top is the script's, never split.
        Outcome lower = both(kb, "s.mDone.frame == \"Nope\" && Number(s.mDone.n) > 1 || true", "t1");
        assertThat(lower.nativeAnswer()).isEmpty();
        assertThat(lower.script()).isEqualTo(true);
    }

    @Test
    void textsOutsideTheSimpleForms_areNotParsed() {
        for (String text : NOT_SIMPLE) {
            assertThat(SimpleCondition.parse(text)).as("'%s'", text).isEmpty();
        }
    }
}
