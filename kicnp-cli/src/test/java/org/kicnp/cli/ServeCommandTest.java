package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The serve, replay and demo verbs are listed and answer --help (the running platform: PlatformTest). */
class ServeCommandTest {
    private static String help(String verb) {
        PrintStream old = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            assertThat(Main.run(verb, "--help")).isZero();
        } finally {
            System.setOut(old);
        }
        return out.toString(StandardCharsets.UTF_8);
    }

    @Test
    void serveHelp_namesEveryOption() {
        assertThat(help("serve")).contains("KB_DIR", "--gateway-port", "--http-port", "--agents",
                "--editor-password-file", "--event-log", "--transport");
    }

    @Test
    void serve_unknownTransport_isAUsageError_beforeAnythingStarts() {
        PrintStream old = System.err;
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code;
        try {
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            code = Main.run("serve", "no-such-kb-dir", "--transport", "carrier-pigeon");
        } finally {
            System.setErr(old);
        }
        assertThat(code).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("carrier-pigeon", "auto, io_uring, epoll, nio");
    }

    @Test
    void replayAndDemoHelp_nameTheirOptions() {
        assertThat(help("replay")).contains("--time-scale", "--drink", "--no-second-visit");
        assertThat(help("demo")).contains("--auto", "--kb", "--http-port");
    }
}
