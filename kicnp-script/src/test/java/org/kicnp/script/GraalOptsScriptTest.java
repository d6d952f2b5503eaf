package org.kicnp.script;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Runs {@code scripts/graal-opts.sh} in bash against a fake target directory and a fake JDK. */
class GraalOptsScriptTest {
    private static final Path SCRIPT = Path.of("..", "scripts", "graal-opts.sh").toAbsolutePath().normalize();

    @TempDir
    Path dir;
    private Path target;
    private Path jdk;

    @BeforeEach
    void layOut() throws IOException {
        target = dir.resolve("with space/target");
        Files.createDirectories(target.resolve("graal/compiler"));
        Files.createDirectories(target.resolve("graal/modules"));
        Files.writeString(target.resolve("graal/compiler/compiler.jar"), "");
        for (String jar : List.of("polyglot", "truffle-api", "truffle-runtime", "truffle-compiler", "js-language")) {
            Files.writeString(target.resolve("graal/modules/" + jar + ".jar"), "");
        }
        jdk = dir.resolve("jdk");
        Files.createDirectories(jdk);
        Files.writeString(jdk.resolve("release"), "MODULES=\"java.base jdk.internal.vm.ci jdk.graal.compiler\"\n");
    }

    private List<String> graalOpts(Map<String, String> env) throws Exception {
        ProcessBuilder builder = new ProcessBuilder("bash", "-c",
                "set -euo pipefail; source \"$0\"; graal_opts \"$1\"", SCRIPT.toString(), target.toString());
        builder.environment().put("JAVA_HOME", jdk.toString());
        builder.environment().remove("KICNP_GRAAL");
        builder.environment().putAll(env);
        builder.redirectErrorStream(true);
        Process process = builder.start();
        String out = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(process.waitFor()).as(out).isZero();
        return out.lines().toList();
    }

    @Test
    void graalOpts_whenJarsPresent_printsOneFlagPerLine() throws Exception {
        List<String> flags = graalOpts(Map.of());

        assertThat(flags).hasSize(6);
        assertThat(flags.get(0)).isEqualTo("-XX:+UnlockExperimentalVMOptions");
        assertThat(flags.get(1)).isEqualTo("-XX:+EnableJVMCI");
        assertThat(flags.get(2)).isEqualTo("--upgrade-module-path=" + target.resolve("graal/compiler/compiler.jar"));
        assertThat(flags.get(3)).startsWith("--module-path=").contains(target.resolve("graal/modules/polyglot.jar").toString())
                .doesNotContain("graal/compiler/");
        assertThat(flags.get(4)).isEqualTo("--add-modules=ALL-MODULE-PATH");
        assertThat(flags.get(5)).isEqualTo("--enable-native-access=ALL-UNNAMED,org.graalvm.truffle");
    }

    @Test
    void graalOpts_whenCompilerMissing_printsNothing() throws Exception {
        Files.delete(target.resolve("graal/compiler/compiler.jar"));

        assertThat(graalOpts(Map.of())).isEmpty();
    }

    @Test
    void graalOpts_whenTruffleRuntimeMissing_printsNothing() throws Exception {
        Files.delete(target.resolve("graal/modules/truffle-runtime.jar"));

        assertThat(graalOpts(Map.of())).isEmpty();
    }

    @Test
    void graalOpts_whenTurnedOff_printsNothing() throws Exception {
        assertThat(graalOpts(Map.of("KICNP_GRAAL", "off"))).isEmpty();
    }

    @Test
    void graalOpts_whenJdkHasNoJvmci_printsNothing() throws Exception {
        Files.writeString(jdk.resolve("release"), "MODULES=\"java.base\"\n");

        assertThat(graalOpts(Map.of())).isEmpty();
    }
}
