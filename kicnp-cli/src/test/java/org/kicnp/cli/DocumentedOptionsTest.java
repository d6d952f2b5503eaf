package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * Every option the README and docs/*.md name for a verb of the command line exists, read from the same picocli model
 * that prints {@code ./kicnp VERB --help}. {@code bench} and {@code test} are the launcher's ({@code bench} is checked
 * in kicnp-bench).
 */
class DocumentedOptionsTest {

    private static final Path ROOT = Path.of("..").toAbsolutePath().normalize();
    private static final List<String> VERBS =
            List.of("validate", "robots", "infer", "serve", "replay", "demo", "agent", "help");

    @Test
    void everyOptionTheDocsNameForAVerb_isAnOptionOfThatVerb() {
        List<DocumentedOptions.Use> uses = DocumentedOptions.uses(DocumentedOptions.docs(ROOT), ROOT, VERBS,
                new CommandLine(new Main()), 0);

        assertThat(uses).as("the docs name options of the verbs (else this test reads nothing)").hasSizeGreaterThan(30);
        assertThat(uses).extracting(DocumentedOptions.Use::command)
                .contains("kicnp serve", "kicnp infer", "kicnp agent sensor", "kicnp replay", "kicnp demo");
        assertThat(uses).filteredOn(u -> !u.known()).isEmpty();
    }

    @Test
    void anOptionAVerbDoesNotHave_isReported_inCodeSpansFencedBlocksAndTheVerbTable(@TempDir Path dir)
            throws IOException {
        Path doc = Files.writeString(dir.resolve("README.md"), String.join("\n",
                "Run `./kicnp serve KB --gateway-prot 7777` or:",
                "```sh",
                "./kicnp agent --as user sensor obstacle 0.4 --ttl 500 --every 5   # a comment --not-read",
                "```",
                "| `replay [KB_DIR] [--time-scale 8] [--speed 2]` | ... |",
                "The word kicnp-cli --frames is not a command line.",
                ""));

        List<DocumentedOptions.Use> uses = DocumentedOptions.uses(List.of(doc), dir, VERBS,
                new CommandLine(new Main()), 0);

        assertThat(uses).extracting(u -> u.command() + " " + u.option() + " " + u.known()).containsExactly(
                "kicnp serve --gateway-prot false",
                "kicnp agent --as true",
                "kicnp agent sensor --ttl true",
                "kicnp agent sensor --every false",
                "kicnp replay --time-scale true",
                "kicnp replay --speed false");
    }
}
