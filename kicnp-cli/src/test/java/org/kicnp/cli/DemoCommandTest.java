package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** {@code kicnp demo --auto}: a scripted User A plays Table 5 to the end and the demo exits 0. */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class DemoCommandTest {
    @Test
    void demoAuto_playsTable5ToTheEnd_printsTheLinesAndExitsZero(@TempDir Path tmp) {
        PrintStream old = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int code;
        try {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            code = Main.run("demo", "--auto", "--kb", tmp.resolve("kb").toString(), "--http-port", "0");
        } finally {
            System.setOut(old);
        }
        String text = out.toString(StandardCharsets.UTF_8);
        old.print(text);
        assertThat(code).isZero();
        assertThat(text).contains("editor:   http://127.0.0.1:", "password in")
                .contains("Robovie: \"Hi, Taro. Nice to meet you. Welcome you to visit my room.\"")
                .contains("Robovie: \"This is a robot dog AIBO. Please enjoy yourself with it.\"")
                .contains("stimulus-to-command latency p50").contains("Table 5 played to the end.");
    }

    /** SIGTERM (kill, a service manager, a closed terminal) stops the simulator and the servers, not only the JVM. */
    @Test
    void demo_stoppedBySigterm_stopsItsSimulatorAndServersCleanly(@TempDir Path tmp) throws Exception {
        Path output = tmp.resolve("demo.out");
        String java = ProcessHandle.current().info().command().orElse("java");
        Process demo = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "demo", "--kb", tmp.resolve("kb").toString(), "--http-port", "0")
                .redirectErrorStream(true).redirectOutput(output.toFile()).start(); // stdin stays open: a person's turn
        try {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (!Files.readString(output).contains("You are User A.") && demo.isAlive()
                    && System.nanoTime() < deadline) {
                Thread.sleep(50);
            }
            assertThat(Files.readString(output)).contains("You are User A.");
            List<ProcessHandle> simulator = demo.descendants().toList();
            assertThat(simulator).as("the simulator subprocess").isNotEmpty();

            demo.destroy(); // SIGTERM

            assertThat(demo.waitFor(30, TimeUnit.SECONDS)).isTrue();
            assertThat(simulator).as("processes left running: %s; the demo printed:%n%s", simulator.stream()
                    .filter(ProcessHandle::isAlive).map(h -> h.pid() + " " + h.info().commandLine().orElse("?")).toList(),
                    Files.readString(output)).noneMatch(ProcessHandle::isAlive);
            assertThat(Files.readString(output)).contains("Demo stopped: the simulator and the servers are shut down.");
        } finally {
            demo.descendants().forEach(ProcessHandle::destroyForcibly);
            demo.destroyForcibly();
        }
    }
}
