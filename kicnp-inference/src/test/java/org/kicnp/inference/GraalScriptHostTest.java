package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptRuntime;

class GraalScriptHostTest {
    private static ScriptRuntime runtime;

    @BeforeAll
    static void start() {
        runtime = ScriptRuntime.create(ScriptConfig.defaults());
    }

    @AfterAll
    static void stop() {
        runtime.close();
    }

    @Test
    void names_matchesWholeIdentifiersOnly() {
        assertThat(GraalScriptHost.names("sendmsg(s.mMouth, 'hi')", "sendmsg")).isTrue();
        assertThat(GraalScriptHost.names("x; Sendmsg(a)", "Sendmsg")).isTrue();
        assertThat(GraalScriptHost.names("Sendmsg(a)", "sendmsg")).isFalse();
        assertThat(GraalScriptHost.names("mysendmsg(a); sendmsg_2()", "sendmsg")).isFalse();
        assertThat(GraalScriptHost.names("a.log", "log")).isTrue();
    }

    @Test
    void run_bindsTheHostFunctionsTheScriptNames_andNoOthers() {
        List<Object> called = new ArrayList<>();
        Map<String, Object> globals = new LinkedHashMap<>();
        globals.put("who", "Ann");
        globals.put("sendmsg", (HostFunction) args -> called.add(args.get(1)));
        globals.put("destroy", (HostFunction) args -> called.add("destroyed"));
        GraalScriptHost host = new GraalScriptHost(runtime);

        host.run("F", "onInstantiate", "sendmsg(who, 'hi ' + who + ' ' + typeof destroy)", globals);
        assertThat(called).containsExactly("hi Ann function");
        called.clear();

        assertThat(host.run("F", "onInstantiate", "typeof globalThis['dest' + 'roy'] + ' ' + who", globals))
                .isEqualTo("undefined Ann");
        assertThatThrownBy(() -> host.run("F", "onInstantiate", "globalThis['send' + 'msg'](who, 'x')", globals))
                .isInstanceOf(RuntimeException.class);
        assertThat(called).isEmpty();
    }
}
