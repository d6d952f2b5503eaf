package org.kicnp.cli.scenario;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.stream.Stream;
import org.kicnp.robots.RepositoryRoot;

/** Finding the scenario in the repository and copying its XML files into a working knowledge-base directory. */
public final class ScenarioFiles {
    private ScenarioFiles() {
    }

    /** The repository holding {@code scenarios/table5} ({@link RepositoryRoot}). */
    public static Optional<Path> repoRoot() {
        return RepositoryRoot.find(ScenarioFiles::holdsTable5);
    }

    static Optional<Path> repoRoot(Optional<String> home, Path start) {
        return RepositoryRoot.find(home, start, ScenarioFiles::holdsTable5);
    }

    private static boolean holdsTable5(Path root) {
        return Files.isDirectory(root.resolve("scenarios/table5"));
    }

    public static Path table5() {
        return repoRoot().map(r -> r.resolve("scenarios/table5")).orElseThrow(() -> new IllegalStateException(
                "Cannot find scenarios/table5 in the working directory or above it (run ./kicnp from the K-ICNP "
                        + "repository, or give the knowledge-base directory)."));
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
