package org.kicnp.robots;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * Where the simulator lives: the repository's {@code robots-sim/} folder and its venv's Python. The venv is made, or
 * brought up to date, with {@code robots-sim/setup-venv.sh} before each start, so a fresh checkout runs (and tests)
 * without a manual step; the script is idempotent and returns at once when the venv is up to date.
 */
public record SimInstallation(Path simDir, Path python) {
    private static final Logger LOG = LoggerFactory.getLogger(SimInstallation.class);
    private static final Duration SETUP_TIMEOUT = Duration.ofMinutes(10);

    /** Finds the repository from {@code repoRoot}, or by walking up from the working directory, and the venv. */
    public static SimInstallation locate(Optional<Path> repoRoot) {
        return locate(repoRoot, SETUP_TIMEOUT);
    }

    static SimInstallation locate(Optional<Path> repoRoot, Duration setupTimeout) {
        Path root = repoRoot.map(Path::toAbsolutePath).orElseGet(SimInstallation::findRoot);
        Path simDir = root.resolve("robots-sim");
        if (!Files.isRegularFile(simDir.resolve("kicnp_sim").resolve("__main__.py"))) {
            throw new SimulatorException("No simulator under '" + simDir + "': expected robots-sim/kicnp_sim there.");
        }
        Path python = simDir.resolve(".venv").resolve("bin").resolve("python");
        // Always: the script returns at once when the venv is up to date, and it alone knows when it is not (a set-up
        // that was interrupted leaves a python without packages; a pull can change requirements.txt).
        try {
            setUpVenv(simDir, setupTimeout);
        } catch (SimulatorException e) {
            if (!Files.isExecutable(python)) {
                throw e;
            }
            // Offline, say: the venv there may well still run the simulator (if not, its exit says why).
            LOG.warn("{} Starting the simulator with the venv as it is.", e.getMessage());
        }
        if (!Files.isExecutable(python)) {
            throw new SimulatorException("robots-sim/setup-venv.sh ran but '" + python + "' is still missing.");
        }
        return new SimInstallation(simDir, python);
    }

    /** The repository holding {@code robots-sim/setup-venv.sh} ({@link RepositoryRoot}). */
    static Path findRoot() {
        return RepositoryRoot.find(SimInstallation::holdsSimulator)
                .orElseThrow(() -> notFound(Path.of("").toAbsolutePath()));
    }

    static Path findRoot(Optional<String> home, Path start) {
        return RepositoryRoot.find(home, start, SimInstallation::holdsSimulator).orElseThrow(() -> notFound(start));
    }

    private static SimulatorException notFound(Path start) {
        return new SimulatorException("No robots-sim/ folder in '" + start + "' or above it: "
                + "run from inside the K-ICNP repository or give the repository root.");
    }

    private static boolean holdsSimulator(Path root) {
        return Files.isRegularFile(root.resolve("robots-sim").resolve("setup-venv.sh"));
    }

    private static void setUpVenv(Path simDir, Duration timeout) {
        Path script = simDir.resolve("setup-venv.sh");
        LOG.debug("Checking the simulator's Python venv with {}", script);
        Path log = null;
        try {
            // Output to a file, not a pipe: reading a pipe to its end would wait for a hung script (and its children).
            log = Files.createTempFile("kicnp-setup-venv", ".log");
            Process p = new ProcessBuilder("bash", script.toString()).redirectErrorStream(true)
                    .redirectOutput(log.toFile()).start();
            if (!p.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS)) {
                // What the script said before we gave up, read before anything is killed: a shell whose child is
                // killed first reports "Killed" on its way out, which is noise in the message.
                String said = Files.readString(log).strip();
                List<ProcessHandle> children = p.descendants().toList(); // once the script is gone they are orphans
                p.destroyForcibly();
                children.forEach(ProcessHandle::destroyForcibly);
                throw new SimulatorException("'" + script + "' did not finish within " + timeout.toSeconds()
                        + " s; its output: " + said);
            }
            if (p.exitValue() != 0) {
                throw new SimulatorException("'" + script + "' failed with exit code " + p.exitValue() + ": "
                        + Files.readString(log).strip());
            }
        } catch (IOException e) {
            throw new SimulatorException("Could not run '" + script + "': " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new SimulatorException("Interrupted while running '" + script + "'.", e);
        } finally {
            if (log != null) {
                try {
                    Files.deleteIfExists(log);
                } catch (IOException e) {
                    LOG.debug("Could not delete {}: {}", log, e.toString());
                }
            }
        }
    }
}
