package org.kicnp.cli.scenario;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.stream.Stream;

/** Finding the scenario in the repository and copying its XML files into a working knowledge-base directory. */
public final class ScenarioFiles {
    private ScenarioFiles() {
    }

    /** The repository holding {@code scenarios/table5}: the working directory or one above it. */
    public static Optional<Path> repoRoot() {
        Path p = Path.of("").toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("scenarios/table5"))) {
            p = p.getParent();
        }
        return Optional.ofNullable(p);
    }

    public static Path table5() {
        return repoRoot().map(r -> r.resolve("scenarios/table5")).orElseThrow(() -> new IllegalStateException(
                "Cannot find scenarios/table5 in the working directory or above it."));
    }

    /** Copies the {@code *.xml} files of a scenario directory into {@code to} (created); returns {@code to}. */
    public static Path copy(Path from, Path to) {
        try (Stream<Path> files = Files.list(from)) {
            Files.createDirectories(to);
            for (Path f : files.filter(p -> p.toString().endsWith(".xml")).toList()) {
                Files.copy(f, to.resolve(f.getFileName()));
            }
            return to;
        } catch (IOException e) {
            throw new UncheckedIOException("Cannot copy the scenario '" + from + "' to '" + to + "': " + e.getMessage(), e);
        }
    }
}
