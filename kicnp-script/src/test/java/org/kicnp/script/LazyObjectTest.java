package org.kicnp.script;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

class LazyObjectTest {
    private static ScriptRuntime runtime;

    @BeforeAll
    static void start() {
        runtime = ScriptRuntime.create(ScriptConfig.defaults());
    }

    @AfterAll
    static void stop() {
        runtime.close();
    }

    /** A frame-like object with a nested member, counting what is read. */
    private record Counting(String name, Map<String, Object> members, List<String> reads) implements ScriptObject {
        @Override public Optional<Object> member(String key) {
            reads.add(name + "." + key);
            return Optional.ofNullable(members.get(key));
        }

        @Override public Set<String> memberKeys() {
            return members.keySet();
        }
    }

    private static Counting user(List<String> reads) {
        Map<String, Object> friend = new LinkedHashMap<>();
        friend.put("name", "Ken");
        friend.put("age", 7L);
        Map<String, Object> user = new LinkedHashMap<>();
        user.put("name", "Ann");
        user.put("friend", new Counting("friend", friend, reads));
        user.put("mood", "happy");
        return new Counting("user", user, reads);
    }

    @Test
    void run_whenScriptReadsOneMemberOfANestedObject_readsOnlyThePathItFollows() {
        List<String> reads = new ArrayList<>();
        Object result = runtime.run(runtime.compile(new ScriptId("Lazy", "read"), "s.friend.name + '/' + s.friend.name"),
                Map.of("s", user(reads)));
        assertThat(result).isEqualTo("Ken/Ken");
        assertThat(reads).as("each member read once per run, nothing else read").containsExactly("user.friend",
                "friend.name");
    }

    @Test
    void run_whenScriptEnumeratesOrMissesMembers_seesAllKeysAndUndefined() {
        List<String> reads = new ArrayList<>();
        Object result = runtime.run(runtime.compile(new ScriptId("Lazy", "keys"),
                "Object.keys(s).join(',') + ':' + (s.nothing === undefined) + ':' + ('mood' in s)"),
                Map.of("s", user(reads)));
        assertThat(result).isEqualTo("name,friend,mood:true:true");
    }

    @Test
    void run_whenScriptPassesTheObjectToAHostFunction_theHostGetsTheSameObjectBack() {
        List<String> reads = new ArrayList<>();
        Counting s = user(reads);
        List<Object> got = new ArrayList<>();
        runtime.run(runtime.compile(new ScriptId("Lazy", "pass"), "f(s.friend)"),
                Map.of("s", s, "f", Proxies.function(args -> {
                    got.addAll(args);
                    return null;
                })));
        assertThat(got).singleElement().isSameAs(s.members().get("friend"));
    }

    @Test
    void run_whenScriptWritesAMember_failsWithAReadOnlyMessage() {
        List<String> reads = new ArrayList<>();
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> runtime.run(
                runtime.compile(new ScriptId("Lazy", "write"), "'use strict'; s.name = 'Bob'"), Map.of("s", user(reads))))
                .isInstanceOf(ScriptFailedException.class).hasMessageContaining("writeMember (name) on read-only object");
    }
}
