package org.kicnp.robots;

import java.nio.file.Path;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * Finding the K-ICNP repository, whose files some verbs need (the simulator under {@code robots-sim/}, the scenario
 * under {@code scenarios/}): the one the {@code ./kicnp} launcher says it runs from (system property
 * {@value #HOME_PROPERTY}), so the verbs work from any working directory, else the first folder from the working
 * directory up that holds what is looked for.
 */
public final class RepositoryRoot {
    /** The system property the {@code ./kicnp} launcher sets to the repository it runs from. */
    public static final String HOME_PROPERTY = "kicnp.home";

    private RepositoryRoot() {
    }

    /** The repository that {@code holds} what the caller needs, or empty when there is none. */
    public static Optional<Path> find(Predicate<Path> holds) {
        return find(Optional.ofNullable(System.getProperty(HOME_PROPERTY)), Path.of("").toAbsolutePath(), holds);
    }

    /** As {@link #find(Predicate)}, with the launcher's {@code home} and the folder to {@code start} from given. */
    public static Optional<Path> find(Optional<String> home, Path start, Predicate<Path> holds) {
        Optional<Path> launcherHome = home.filter(h -> !h.isBlank()).map(h -> Path.of(h).toAbsolutePath())
                .filter(holds);
        if (launcherHome.isPresent()) {
            return launcherHome;
        }
        for (Path p = start; p != null; p = p.getParent()) {
            if (holds.test(p)) {
                return Optional.of(p);
            }
        }
        return Optional.empty();
    }
}
