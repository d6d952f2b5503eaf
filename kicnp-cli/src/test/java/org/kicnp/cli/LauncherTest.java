package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code ./kicnp} launcher's own logic (finding a JDK, the {@code test} verb's help), run with bash against
 * fake JDK directories, so no build is started.
 */
class LauncherTest {
    private static final Path LAUNCHER = Path.of("..", "kicnp").toAbsolutePath().normalize();

    @TempDir
    Path jvms;

    @Test
    void findJdk_whenJavaHomeIsTooOld_picksTheNewestRecentEnoughUnderTheJvmDirectory() throws Exception {
        Path old = fakeJdk("jdk-17", "17.0.2", true);
        fakeJdk("jdk-21", "21.0.5", false);
        Path newest = fakeJdk("jdk-25", "25.0.1", true);

        Run run = bash("source \"$LAUNCHER\"; find_jdk", Map.of("JAVA_HOME", old.toString()));

        assertThat(run.code()).isZero();
        assertThat(run.out().strip()).isEqualTo(newest.toString());
    }

    @Test
    void findJdk_whenJavaHomeIsRecentEnough_keepsIt() throws Exception {
        Path home = fakeJdk("jdk-21", "21.0.5", false);
        fakeJdk("jdk-25", "25.0.1", true);

        Run run = bash("source \"$LAUNCHER\"; find_jdk", Map.of("JAVA_HOME", home.toString()));

        assertThat(run.out().strip()).isEqualTo(home.toString());
    }

    @Test
    void launcher_whenNoJdkIsRecentEnough_explainsAndExitsWithTwo() throws Exception {
        Path old = fakeJdk("jdk-17", "17.0.2", true);

        Run run = bash("\"$LAUNCHER\" --help", Map.of("JAVA_HOME", old.toString()));

        assertThat(run.code()).isEqualTo(2);
        assertThat(run.out()).isEmpty();
        assertThat(run.err()).contains("K-ICNP needs a JDK 21 or newer; found: JAVA_HOME=" + old + " (17)")
                .contains("apt-get install openjdk-21-jdk-headless").contains("set JAVA_HOME");
    }

    @Test
    void testVerb_help_explainsWithoutRunningAnything() throws Exception {
        fakeJdk("jdk-25", "25.0.1", true);

        Run run = bash("\"$LAUNCHER\" test --help", Map.of());

        assertThat(run.code()).isZero();
        assertThat(run.out()).contains("Usage: kicnp test").contains("./mvnw -B verify").contains("pytest");
    }

    /** A directory that looks like a JDK: bin/java printing the version, bin/javac, and maybe a release file. */
    private Path fakeJdk(String name, String version, boolean releaseFile) throws IOException {
        Path home = Files.createDirectories(jvms.resolve(name).resolve("bin")).getParent();
        script(home.resolve("bin/java"), "echo 'openjdk version \"" + version + "\" 2025-01-01' >&2");
        script(home.resolve("bin/javac"), "exit 0");
        if (releaseFile) {
            Files.writeString(home.resolve("release"), "IMPLEMENTOR=\"Test\"\nJAVA_VERSION=\"" + version + "\"\n");
        }
        return home;
    }

    private static void script(Path file, String body) throws IOException {
        Files.writeString(file, "#!/bin/sh\n" + body + "\n");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rwxr-xr-x"));
    }

    private record Run(int code, String out, String err) {
    }

    private Run bash(String command, Map<String, String> env) throws Exception {
        ProcessBuilder pb = new ProcessBuilder(List.of("bash", "-c", command));
        pb.environment().remove("JAVA_HOME");
        pb.environment().putAll(env);
        pb.environment().put("KICNP_JVM_DIR", jvms.toString());
        pb.environment().put("LAUNCHER", LAUNCHER.toString());
        Process p = pb.redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null"))).start();
        byte[] out = p.getInputStream().readAllBytes();
        byte[] err = p.getErrorStream().readAllBytes();
        assertThat(p.waitFor(30, TimeUnit.SECONDS)).as("launcher finished").isTrue();
        return new Run(p.exitValue(), new String(out, StandardCharsets.UTF_8), new String(err, StandardCharsets.UTF_8));
    }
}
