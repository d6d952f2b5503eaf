package org.kicnp.script;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Instant;
import java.time.Duration;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

class ScriptValuesTest {
    private static final ScriptId ID = new ScriptId("Values", "onNeeded");
    private static ScriptRuntime runtime;

    @BeforeAll
    static void start() {
        runtime = ScriptRuntime.create(ScriptConfig.defaults().withTimeLimit(Duration.ofSeconds(10)));
    }

    @AfterAll
    static void stop() {
        runtime.close();
    }

    private static Object eval(String source, Map<String, ?> globals) {
        return runtime.run(runtime.compile(ID, source), globals);
    }

    @Test
    void toJava_convertsPrimitives() {
        assertThat(eval("'a' + 1", Map.of())).isEqualTo("a1");
        assertThat(eval("3.0", Map.of())).isEqualTo(3L);
        assertThat(eval("1.5", Map.of())).isEqualTo(1.5);
        assertThat(eval("2 ** 70", Map.of())).isEqualTo(Math.pow(2, 70));
        assertThat(eval("true", Map.of())).isEqualTo(true);
        assertThat(eval("null", Map.of())).isSameAs(Undefined.INSTANCE);
        assertThat(eval("undefined", Map.of())).isSameAs(ScriptRuntime.UNDEFINED);
        assertThat(eval("10n", Map.of())).isEqualTo(10L);
    }

    @Test
    void toJava_convertsArraysAndObjectsDeeply() {
        Object result = eval("({name: 'Ann', tags: ['a', 1, null], inner: {ok: true}})", Map.of());

        assertThat(result).isEqualTo(Map.of("name", "Ann", "tags", List.of("a", 1L, Undefined.INSTANCE),
                "inner", Map.of("ok", true)));
    }

    @Test
    void toJava_whenResultIsFunctionOrDate_givesTextAndInstant() {
        assertThat(eval("(function f() { return 1; })", Map.of())).asString().contains("function f");
        assertThat(eval("new Date(0)", Map.of())).isEqualTo(Instant.EPOCH);
    }

    @Test
    void toJava_whenProxyComesBack_givesTheJavaValueItWasBuiltFrom() {
        Map<String, Object> user = Map.of("name", "Ann");

        assertThat(eval("u", Map.of("u", user))).isEqualTo(user);
        assertThat(eval("u.list", Map.of("u", Map.of("list", List.of(1, 2))))).isEqualTo(List.of(1, 2));
    }

    @Test
    void toGuest_convertsNestedMapsListsAndCoreValues() {
        Map<String, Object> s = Map.of("mUser", Map.of("name", "Ann", "likes", List.of("tea", "cake")),
                "age", org.kicnp.core.Value.of(5L), "robot", org.kicnp.core.Value.ref("RobotA"));

        assertThat(eval("s.mUser.name + ' likes ' + s.mUser.likes[1] + ' ' + s.mUser.likes.length", Map.of("s", s)))
                .isEqualTo("Ann likes cake 2");
        assertThat(eval("s.age + 1", Map.of("s", s))).isEqualTo(6L);
        assertThat(eval("s.robot", Map.of("s", s))).isEqualTo("RobotA");
        assertThat(eval("Object.keys(s.mUser).length", Map.of("s", s))).isEqualTo(2L);
    }

    @Test
    void proxyObject_isReadOnly() {
        Map<String, Object> s = Map.of("x", 1);

        assertThat(eval("'use strict'; try { s.x = 2; 'written' } catch (e) { 'refused' }", Map.of("s", s)))
                .isEqualTo("refused");
        assertThat(eval("// strict\n\"use strict\"; try { s.x = 2; 'written' } catch (e) { 'refused' }", Map.of("s", s)))
                .isEqualTo("refused");
        assertThat(eval("try { s.x = 2; } catch (e) {} s.x", Map.of("s", s))).isEqualTo(1L);
    }

    @Test
    void function_convertsArgumentsAndResult() {
        Object result = eval("add(2, 3.5, [1])", Map.of("add", Proxies.function(args -> List.of(args.get(0), args.get(1),
                args.get(2)))));

        assertThat(result).isEqualTo(List.of(2L, 3.5, List.of(1L)));
    }
}
