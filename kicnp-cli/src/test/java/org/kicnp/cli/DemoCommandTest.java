package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
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
}
