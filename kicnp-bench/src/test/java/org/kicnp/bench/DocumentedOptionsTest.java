package org.kicnp.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.cli.DocumentedOptions;
import picocli.CommandLine;

/**
 * Every option the README and docs/*.md (but the records of past runs, benchmarks.md) name for {@code ./kicnp bench}
 * and its benchmarks exists, read from the picocli model that prints {@code ./kicnp bench BENCHMARK --help}.
 */
class DocumentedOptionsTest {

    private static final Path ROOT = Path.of("..").toAbsolutePath().normalize();

    @Test
    void everyOptionTheDocsNameForABenchmark_isAnOptionOfThatBenchmark() {
        List<DocumentedOptions.Use> uses = DocumentedOptions.uses(DocumentedOptions.docs(ROOT), ROOT,
                List.of("bench"), new CommandLine(new BenchMain()), 1);

        assertThat(uses).extracting(DocumentedOptions.Use::command)
                .contains("kicnp bench core", "kicnp bench inference", "kicnp bench gateway");
        assertThat(uses).filteredOn(u -> !u.known()).isEmpty();
    }

    @Test
    void anOptionABenchmarkDoesNotHave_isReported(@TempDir Path dir) throws IOException {
        Path doc = Files.writeString(dir.resolve("README.md"), String.join("\n",
                "| `bench core [--frames N] [--warm 3]` | ... |",
                "Run `./kicnp bench gateway --agents 100 --transport nio --clients 4`.",
                ""));

        List<DocumentedOptions.Use> uses = DocumentedOptions.uses(List.of(doc), dir, List.of("bench"),
                new CommandLine(new BenchMain()), 1);

        assertThat(uses).extracting(u -> u.command() + " " + u.option() + " " + u.known()).containsExactly(
                "kicnp bench core --frames true",
                "kicnp bench core --warm false",
                "kicnp bench gateway --agents true",
                "kicnp bench gateway --transport true",
                "kicnp bench gateway --clients false");
    }
}
