package org.kicnp.script;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

class ScriptRuntimeTest {
    private static final ScriptId GREETING = new ScriptId("Greeting", "onInstantiate");
    private static ScriptRuntime runtime;

    @BeforeAll
    static void start() {
        runtime = ScriptRuntime.create(ScriptConfig.defaults().withTimeLimit(Duration.ofSeconds(10)));
    }

    @AfterAll
    static void stop() {
        runtime.close();
    }

    @Test
    void run_whenStatementCallsHostFunction_passesConvertedArguments() {
        List<List<Object>> calls = Collections.synchronizedList(new ArrayList<>());
        CompiledScript script = runtime.compile(GREETING, "Sendmsg(s.mMouth, 'Hi!');");

        Object result = runtime.run(script, Map.of(
                "s", Proxies.object(Map.of("mMouth", "mouth1")),
                "Sendmsg", Proxies.procedure(calls::add)));

        assertThat(calls).containsExactly(List.of("mouth1", "Hi!"));
        assertThat(result).isSameAs(ScriptRuntime.UNDEFINED);
    }

    @Test
    void warmUpBuiltIns_runInTheSandbox_withTheResultsJavaScriptGives() {
        // The start-up warm-up only logs a warning when it fails; this shows it does what it says in the sandbox.
        CompiledScript warmUp = runtime.compile(new ScriptId("warm-up", "built-ins"), ScriptRuntime.WARM_UP_BUILT_INS);

        assertThat(runtime.run(warmUp, Map.of())).isEqualTo("0.251,2{\"a\":[1]}2");
    }

    @Test
    void test_whenConditionIsExpression_returnsItsTruthiness() {
        CompiledScript condition = runtime.compile(new ScriptId("Greeting", "mUser"), "s.mUser.age > 3");

        assertThat(runtime.test(condition, Map.of("s", Map.of("mUser", Map.of("age", 5))))).isTrue();
        assertThat(runtime.test(condition, Map.of("s", Map.of("mUser", Map.of("age", 2))))).isFalse();
    }

    @Test
    void test_usesJavaScriptTruthiness() {
        assertThat(runtime.test(runtime.compile(GREETING, "''"), Map.of())).isFalse();
        assertThat(runtime.test(runtime.compile(GREETING, "0"), Map.of())).isFalse();
        assertThat(runtime.test(runtime.compile(GREETING, "NaN"), Map.of())).isFalse();
        assertThat(runtime.test(runtime.compile(GREETING, "null"), Map.of())).isFalse();
        assertThat(runtime.test(runtime.compile(GREETING, "undefined"), Map.of())).isFalse();
        assertThat(runtime.test(runtime.compile(GREETING, "'x'"), Map.of())).isTrue();
        assertThat(runtime.test(runtime.compile(GREETING, "({})"), Map.of())).isTrue();
        assertThat(runtime.test(runtime.compile(GREETING, "[]"), Map.of())).isTrue();
        assertThat(runtime.test(runtime.compile(GREETING, "-1"), Map.of())).isTrue();
    }

    @Test
    void run_whenScriptDeclaresLet_canRunAgainInTheSameContext() {
        CompiledScript script = runtime.compile(GREETING, "let greeting = 'Hi ' + name; greeting");

        for (int i = 0; i < 5; i++) {
            assertThat(runtime.run(script, Map.of("name", "Ann" + i))).isEqualTo("Hi Ann" + i);
        }
    }

    @Test
    void run_whenGlobalNotBound_failsWithReferenceError() {
        runtime.run(runtime.compile(GREETING, "typeof user"), Map.of("user", "x"));
        CompiledScript script = runtime.compile(GREETING, "user.length");

        assertThatThrownBy(() -> runtime.run(script, Map.of()))
                .isInstanceOf(ScriptFailedException.class)
                .hasMessageContaining("ReferenceError");
    }

    @Test
    void compile_whenSyntaxError_reportsIdLineAndColumn() {
        assertThatThrownBy(() -> runtime.compile(GREETING, "var a = 1;\nSendmsg(s.mMouth, 'Hi';\n"))
                .isInstanceOfSatisfying(ScriptSyntaxException.class, e -> {
                    assertThat(e.id()).isEqualTo(GREETING);
                    assertThat(e.line()).isEqualTo(2);
                    assertThat(e.column()).isEqualTo(23);
                    assertThat(e.parserMessage()).isEqualTo("Expected , but found ;");
                })
                .hasMessage("Script in slot 'onInstantiate' of frame 'Greeting' has a syntax error at line 2, column 23: "
                        + "Expected , but found ;");
    }

    @Test
    void compile_whenBlockUnclosed_reportsEndOfTheTextAsWritten() {
        assertThatThrownBy(() -> runtime.compile(GREETING, "if (x) {"))
                .isInstanceOfSatisfying(ScriptSyntaxException.class, e -> {
                    assertThat(e.line()).isEqualTo(1);
                    assertThat(e.column()).isEqualTo(9);
                    assertThat(e.parserMessage()).isEqualTo("Expected } but found eof");
                });
    }

    @Test
    void compile_whenTextTriesToCloseTheWrappingBlock_isASyntaxError() {
        assertThatThrownBy(() -> runtime.compile(GREETING, "x }{ y"))
                .isInstanceOf(ScriptSyntaxException.class);
        assertThatThrownBy(() -> runtime.compile(GREETING, "return 1"))
                .isInstanceOf(ScriptSyntaxException.class)
                .hasMessageContaining("Invalid return statement");
    }

    @Test
    void compile_whenSameIdAndText_returnsCachedScriptWithoutParsing() {
        ScriptId id = new ScriptId("Cache", "onNeeded");
        CompiledScript first = runtime.compile(id, "1 + 1");
        long parses = runtime.parseCount();

        CompiledScript second = runtime.compile(id, "1 + 1");
        CompiledScript other = runtime.compile(id, "1 + 2");

        assertThat(second).isSameAs(first);
        assertThat(other).isNotSameAs(first);
        assertThat(runtime.parseCount()).isEqualTo(parses + 1);
    }

    @Test
    void run_whenScriptThrows_reportsMessageAndLine() {
        CompiledScript script = runtime.compile(GREETING, "var x = 1;\nthrow new Error('no mouth');");

        assertThatThrownBy(() -> runtime.run(script, Map.of()))
                .isInstanceOfSatisfying(ScriptFailedException.class, e -> {
                    assertThat(e.line()).hasValue(2);
                    assertThat(e.scriptMessage()).isEqualTo("Error: no mouth");
                })
                .hasMessage("Script in slot 'onInstantiate' of frame 'Greeting' failed at line 2: Error: no mouth");
        assertThat(runtime.run(runtime.compile(GREETING, "40 + 2"), Map.of())).isEqualTo(42L);
    }

    @Test
    void run_whenHostFunctionThrows_keepsJavaExceptionAsCause() {
        IllegalStateException boom = new IllegalStateException("mouth is busy");
        CompiledScript script = runtime.compile(GREETING, "Sendmsg('m', 'x')");

        assertThatThrownBy(() -> runtime.run(script, Map.of("Sendmsg", Proxies.procedure(a -> {
            throw boom;
        }))))
                .isInstanceOf(ScriptFailedException.class)
                .hasCause(boom)
                .hasMessageContaining("mouth is busy");
    }

    @Test
    void run_whenHostFunctionRunsAnotherScript_nestedRunUsesItsOwnContext() {
        CompiledScript inner = runtime.compile(new ScriptId("Inner", "onAdded"), "'inner sees ' + s.x");
        CompiledScript outer = runtime.compile(GREETING, "let before = s.x; Fire() + ' and outer still sees ' + s.x + before");

        Object result = runtime.run(outer, Map.of("s", Map.of("x", "A"),
                "Fire", Proxies.function(args -> runtime.run(inner, Map.of("s", Map.of("x", "B"))))));

        assertThat(result).isEqualTo("inner sees B and outer still sees AA");
    }

    @Test
    void run_whenScriptDefinesVar_doesNotLeakIntoTheNextRunsGlobals() {
        runtime.run(runtime.compile(GREETING, "var leaked = 1; s.x"), Map.of("s", Map.of("x", 1)));

        for (int i = 0; i < 20; i++) {
            assertThat(runtime.run(runtime.compile(GREETING, "typeof s"), Map.of())).isEqualTo("undefined");
        }
    }

    @Test
    void run_whenScriptCompiledByAnotherRuntime_refuses() {
        try (ScriptRuntime other = ScriptRuntime.create(ScriptConfig.defaults())) {
            CompiledScript foreign = other.compile(GREETING, "1");

            assertThatThrownBy(() -> runtime.run(foreign, Map.of()))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("The script Greeting.onInstantiate was compiled by another script runtime.");
        }
    }

    @Test
    void run_whenRuntimeClosed_refuses() {
        ScriptRuntime closed = ScriptRuntime.create(ScriptConfig.defaults());
        CompiledScript script = closed.compile(GREETING, "1");
        closed.close();

        assertThatThrownBy(() -> closed.run(script, Map.of()))
                .isInstanceOf(IllegalStateException.class)
                .hasMessage("The script runtime is closed.");
    }
}
