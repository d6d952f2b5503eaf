package org.kicnp.script;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.Map;
import java.util.Set;

import org.graalvm.polyglot.HostAccess;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
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

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', quoteCharacter = '"', textBlock = """
        Java.type('java.io.File')                                  | Access to host class java.io.File is not allowed
        Java.type('java.lang.System').exit(3)                      | Access to host class java.lang.System is not allowed
        Java.type('java.lang.Runtime').getRuntime().exec('true')   | Access to host class java.lang.Runtime is not allowed
        Java.type('java.lang.ProcessBuilder')                      | Access to host class java.lang.ProcessBuilder is not allowed
        Java.type('java.lang.Thread')                              | Access to host class java.lang.Thread is not allowed
        Java.type('java.lang.Class').forName('java.io.File')       | Access to host class java.lang.Class is not allowed
        Java.type('java.lang.reflect.Method')                      | Access to host class java.lang.reflect.Method is not allowed
        java.lang.System.exit(3)                                   | System.exit is not a function
        Packages.java.lang.System.exit(3)                          | System.exit is not a function
        Java.addToClasspath('/tmp')                                | Host class loading is not allowed
        Java.type('java.lang.Math').class.forName('java.io.File')  | Unknown identifier: forName
        Java.type('java.lang.Math').class.getMethods()             | Unknown identifier: getMethods
        Java.type('java.lang.Math').getClass()                     | Unknown identifier: getClass
        load('/etc/passwd')                                        | Operation is not allowed for: /etc/passwd
        require('fs')                                              | ReferenceError: require is not defined
        Polyglot.eval('python', '1')                               | ReferenceError: Polyglot is not defined
        Polyglot.eval('js', '1')                                   | ReferenceError: Polyglot is not defined
        process.env.HOME                                           | ReferenceError: process is not defined
        read('/etc/passwd')                                        | ReferenceError: read is not defined
        readFully('/etc/passwd')                                   | ReferenceError: readFully is not defined
        readline()                                                 | ReferenceError: readline is not defined
        quit(3)                                                    | ReferenceError: quit is not defined
        exit(3)                                                    | ReferenceError: exit is not defined
        new Worker('x.js')                                         | ReferenceError: Worker is not defined
        """)
    void run_whenScriptReachesOutsideTheSandbox_failsClearlyAndRuntimeKeepsWorking(String attempt, String reason) {
        CompiledScript script = runtime.compile(ID, attempt);

        assertThatThrownBy(() -> runtime.run(script, Map.of()))
                .isInstanceOf(ScriptFailedException.class)
                .hasMessageStartingWith("Script in slot 'onInstantiate' of frame 'Intruder' failed at line 1: ")
                .hasMessageContaining(reason);
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
    void run_whenScriptLogs_writesNothingToStandardOutput() {
        PrintStream original = System.out;
        ByteArrayOutputStream captured = new ByteArrayOutputStream();
        System.setOut(new PrintStream(captured, true, StandardCharsets.UTF_8));
        try (ScriptRuntime fresh = ScriptRuntime.create(ScriptConfig.defaults())) {
            // Created while System.out is captured: GraalJS would take that stream as its default output.
            fresh.run(fresh.compile(ID, "console.log('leak?'); print('leak?'); 1"), Map.of());
        } finally {
            System.setOut(original);
        }

        assertThat(captured.toString(StandardCharsets.UTF_8)).doesNotContain("leak?");
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
