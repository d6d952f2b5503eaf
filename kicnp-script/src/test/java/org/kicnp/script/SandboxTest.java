package org.kicnp.script;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.Map;
import java.util.Set;

import org.graalvm.polyglot.HostAccess;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

class SandboxTest {
    private static final ScriptId ID = new ScriptId("Intruder", "onInstantiate");
    private static ScriptRuntime runtime;

    @BeforeAll
    static void start() {
        runtime = ScriptRuntime.create(ScriptConfig.defaults()
                .withTimeLimit(Duration.ofSeconds(10))
                .withAllowedHostClasses(Set.of("java.lang.Math")));
    }

    @AfterAll
    static void stop() {
        runtime.close();
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "Java.type('java.io.File')",
        "Java.type('java.lang.System').exit(3)",
        "Java.type('java.lang.Runtime').getRuntime().exec('true')",
        "Java.type('java.lang.Thread')",
        "Java.type('java.lang.Class').forName('java.io.File')",
        "java.lang.System.exit(3)",
        "Packages.java.lang.System.exit(3)",
        "load('/etc/passwd')",
        "require('fs')",
        "Polyglot.eval('python', '1')",
        "Polyglot.eval('js', '1')",
        "Polyglot.import('x')",
        "process.env.HOME",
        "read('/etc/passwd')",
        "readFully('/etc/passwd')",
        "readline()",
        "quit(3)",
        "exit(3)",
        "new Worker('x.js')",
        "importScripts('/etc/passwd')",
        "Java.type('java.lang.Math').class.forName('java.io.File')",
        "Java.type('java.lang.Math').getClass()",
        "Java.type('java.lang.Math').class.getClassLoader()",
    })
    void run_whenScriptReachesOutsideTheSandbox_failsAndRuntimeKeepsWorking(String attempt) {
        CompiledScript script = runtime.compile(ID, attempt);

        assertThatThrownBy(() -> runtime.run(script, Map.of()))
                .isInstanceOf(ScriptFailedException.class)
                .hasMessageStartingWith("Script in slot 'onInstantiate' of frame 'Intruder' failed");
        assertThat(runtime.run(runtime.compile(ID, "1 + 1"), Map.of())).isEqualTo(2L);
    }

    @Test
    void run_whenClassIsAllowListed_canCallItsStaticMethods() {
        CompiledScript script = runtime.compile(ID, "Java.type('java.lang.Math').max(1, 2)");

        assertThat(runtime.run(script, Map.of())).isEqualTo(2L);
    }

    @Test
    void run_whenHostObjectPassed_exposesOnlyExportedMembers() {
        Mouth mouth = new Mouth();

        assertThat(runtime.run(runtime.compile(ID, "m.say('hi')"), Map.of("m", mouth))).isEqualTo("said hi");
        assertThatThrownBy(() -> runtime.run(runtime.compile(ID, "m.secret()"), Map.of("m", mouth)))
                .isInstanceOf(ScriptFailedException.class);
        assertThatThrownBy(() -> runtime.run(runtime.compile(ID, "m.getClass().forName('java.io.File')"), Map.of("m", mouth)))
                .isInstanceOf(ScriptFailedException.class);
    }

    @Test
    void create_whenAllowListNamesUnknownClass_saysWhich() {
        ScriptConfig config = ScriptConfig.defaults().withAllowedHostClasses(Set.of("no.such.Clazz"));

        assertThatThrownBy(() -> ScriptRuntime.create(config))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("The allow-listed script class 'no.such.Clazz' does not exist.");
    }

    /** A host object with one exported and one hidden method. */
    public static final class Mouth {
        @HostAccess.Export
        public String say(String text) {
            return "said " + text;
        }

        public String secret() {
            return "secret";
        }
    }
}
