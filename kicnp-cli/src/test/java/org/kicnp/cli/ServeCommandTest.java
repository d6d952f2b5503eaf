package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

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
                "--editor-password-file", "--event-log", "--transport", "--listen", "--tls-keystore", "--tls-password-file",
                "--plaintext-listen");
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
    void serve_whenTheKnowledgeBaseHasErrors_printsThemInWordsWithoutAStackTrace(@TempDir Path kb) throws Exception {
        Files.writeString(kb.resolve("cycle.xml"), """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>A</NAME><ISA>B</ISA></FRAME>
                  <FRAME><NAME>B</NAME><ISA>A</ISA></FRAME>
                </KNOWLEDGEBASE>
                """);

        CliRun run = CliRun.of("serve", kb.toString(), "--gateway-port", "0", "--http-port", "0");

        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains("kicnp serve: " + kb.resolve("cycle.xml") + ":2:")
                .contains("Frame 'A' is a kind of 'B', which makes an IS-A cycle")
                .doesNotContain("\tat ", "KnowledgeXmlException");
    }

    @Test
    void serve_withAnEmptyPasswordFile_saysSoInOneSentence(@TempDir Path kb) throws Exception {
        Path password = Files.writeString(kb.resolve("password"), "\n");

        CliRun run = CliRun.of("serve", kb.toString(), "--gateway-port", "0", "--http-port", "0",
                "--editor-password-file", password.toString());

        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains("kicnp serve: The editor password file '" + password + "' is empty.")
                .doesNotContain("Exception");
    }

    @Test
    void replayAndDemoHelp_nameTheirOptions() {
        assertThat(help("replay")).contains("--time-scale", "--drink", "--no-second-visit");
        assertThat(help("demo")).contains("--auto", "--kb", "--http-port");
    }
}
