package org.kicnp.robots;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

/** Finding the simulator, making its venv when missing, and a simulator that dies before saying hello. */
class SimInstallationTest {
    @TempDir
    Path repo;

    private Path fakeSim(String setupScript) throws IOException {
        Path sim = Files.createDirectories(repo.resolve("robots-sim"));
        Files.createDirectories(sim.resolve("kicnp_sim"));
        Files.writeString(sim.resolve("kicnp_sim").resolve("__main__.py"), "");
        Files.writeString(sim.resolve("setup-venv.sh"), setupScript);
        return sim;
    }

    @Test
    void locate_whenTheVenvIsMissing_runsSetupVenvFirst() throws IOException {
        Path sim = fakeSim("""
                mkdir -p "$(dirname "$0")/.venv/bin"
                printf '#!/bin/sh\\n' > "$(dirname "$0")/.venv/bin/python"
                chmod +x "$(dirname "$0")/.venv/bin/python"
                touch "$(dirname "$0")/setup-ran"
                """);

        SimInstallation found = SimInstallation.locate(Optional.of(repo));

        assertThat(found.python()).isEqualTo(sim.resolve(".venv/bin/python"));
        assertThat(sim.resolve("setup-ran")).exists();
    }

    @Test
    void locate_whenTheVenvExistsButItsSetUpDidNotFinish_runsSetupVenvAgain() throws IOException {
        Path sim = fakeSim("touch \"$(dirname \"$0\")/setup-ran\"\n");
        Path python = Files.createDirectories(sim.resolve(".venv/bin")).resolve("python"); // no packages, no stamp
        Files.writeString(python, "#!/bin/sh\n");
        Files.setPosixFilePermissions(python, PosixFilePermissions.fromString("rwxr-xr-x"));

        SimInstallation.locate(Optional.of(repo));

        assertThat(sim.resolve("setup-ran")).exists();
    }

    @Test
    @Timeout(value = 20, unit = TimeUnit.SECONDS)
    void locate_whenTheSetupScriptHangs_givesUpAfterTheTimeoutSayingSo() throws IOException, InterruptedException {
        Path sim = fakeSim("echo 'pip: connecting...'\nsleep 60 &\necho $! > \"$(dirname \"$0\")/child.pid\"\nwait\n");

        long start = System.nanoTime();
        assertThatThrownBy(() -> SimInstallation.locate(Optional.of(repo), Duration.ofSeconds(1)))
                .isInstanceOf(SimulatorException.class)
                .hasMessageEndingWith("setup-venv.sh' did not finish within 1 s; its output: pip: connecting...");
        assertThat(System.nanoTime() - start).isLessThan(TimeUnit.SECONDS.toNanos(5));
        // nothing the script started is left behind
        long child = Long.parseLong(Files.readString(sim.resolve("child.pid")).strip());
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (running(child) && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        assertThat(running(child)).as("the script's child %d still running", child).isFalse();
    }

    /**
     * Whether a process is alive and not a zombie: a killed orphan stays a zombie until whatever init the machine has
     * reaps it, and {@link ProcessHandle#isAlive()} counts a zombie as alive.
     */
    private static boolean running(long pid) throws IOException {
        if (ProcessHandle.of(pid).filter(ProcessHandle::isAlive).isEmpty()) {
            return false;
        }
        Path stat = Path.of("/proc", Long.toString(pid), "stat");
        try {
            String line = Files.readString(stat);
            return line.charAt(line.lastIndexOf(')') + 2) != 'Z'; // "pid (comm) S ..."
        } catch (java.nio.file.NoSuchFileException gone) {
            return false;
        }
    }

    @Test
    @Timeout(value = 20, unit = TimeUnit.SECONDS)
    void start_whenTheSimulatorsFirstLineIsNotAValidHello_failsAtOnceQuotingIt() throws IOException {
        Path sim = fakeSim("exit 0\n");
        Path python = Files.createDirectories(sim.resolve(".venv/bin")).resolve("python");
        Files.writeString(python, "#!/bin/sh\necho '{\"type\":\"hello\",\"t\":0.0,\"protocol\":\"kicnp-sim/1\"}'\nsleep 30\n");
        Files.setPosixFilePermissions(python, PosixFilePermissions.fromString("rwxr-xr-x"));

        long start = System.nanoTime();
        assertThatThrownBy(() -> SimWorld.start(SimOptions.defaults().withRepoRoot(repo)))
                .isInstanceOf(SimulatorException.class)
                .hasMessageContaining("not a valid hello")
                .hasMessageContaining("member 'seed' is missing");
        assertThat(System.nanoTime() - start).isLessThan(TimeUnit.SECONDS.toNanos(8));
    }

    @Test
    @Timeout(value = 20, unit = TimeUnit.SECONDS)
    void start_whenTheSimulatorSpeaksAnotherProtocolVersion_failsNamingBoth() throws IOException {
        Path sim = fakeSim("exit 0\n");
        Path python = Files.createDirectories(sim.resolve(".venv/bin")).resolve("python");
        Files.writeString(python, "#!/bin/sh\necho '{\"type\":\"hello\",\"t\":0.0,\"protocol\":\"kicnp-sim/2\","
                + "\"seed\":1,\"mode\":\"manual\",\"robots\":{}}'\nsleep 30\n");
        Files.setPosixFilePermissions(python, PosixFilePermissions.fromString("rwxr-xr-x"));

        assertThatThrownBy(() -> SimWorld.start(SimOptions.defaults().withRepoRoot(repo)))
                .isInstanceOf(SimulatorException.class)
                .hasMessageContaining("speaks kicnp-sim/2; this platform speaks kicnp-sim/1");
    }

    @Test
    void locate_whenTheVenvExistsButCannotBeUpdated_startsWithTheVenvThereIs() throws IOException {
        Path sim = fakeSim("echo 'pip: no network'; exit 1\n"); // say, offline after a pin changed
        Path python = Files.createDirectories(sim.resolve(".venv/bin")).resolve("python");
        Files.writeString(python, "#!/bin/sh\n");
        Files.setPosixFilePermissions(python, PosixFilePermissions.fromString("rwxr-xr-x"));

        assertThat(SimInstallation.locate(Optional.of(repo)).python()).isEqualTo(python);
    }

    @Test
    void findRoot_fromOutsideTheRepository_usesTheRepositoryTheLauncherNames(@TempDir Path elsewhere)
            throws IOException {
        fakeSim("exit 0\n");

        assertThat(SimInstallation.findRoot(Optional.of(repo.toString()), elsewhere)).isEqualTo(repo.toAbsolutePath());
        assertThatThrownBy(() -> SimInstallation.findRoot(Optional.empty(), elsewhere))
                .isInstanceOf(SimulatorException.class).hasMessageContaining("No robots-sim/ folder in '" + elsewhere);
        // a launcher home without the simulator does not hide the one found from the working directory
        assertThat(SimInstallation.findRoot(Optional.of(elsewhere.toString()), repo.resolve("robots-sim")))
                .isEqualTo(repo);
    }

    @Test
    void locate_whenTheSetupScriptFails_reportsItsExitCodeAndOutput() throws IOException {
        fakeSim("echo 'pip: no network'; exit 3\n");

        assertThatThrownBy(() -> SimInstallation.locate(Optional.of(repo)))
                .isInstanceOf(SimulatorException.class)
                .hasMessageEndingWith("setup-venv.sh' failed with exit code 3: pip: no network");
    }

    @Test
    void start_whenTheSimulatorExitsBeforeHello_failsQuotingItsLastWords() throws IOException {
        Path sim = fakeSim("exit 0\n");
        Path python = Files.createDirectories(sim.resolve(".venv/bin")).resolve("python");
        Files.writeString(python, "#!/bin/sh\necho 'ModuleNotFoundError: No module named pymunk' >&2\nexit 1\n");
        Files.setPosixFilePermissions(python, PosixFilePermissions.fromString("rwxr-xr-x"));

        assertThatThrownBy(() -> SimWorld.start(SimOptions.defaults().withRepoRoot(repo)))
                .isInstanceOf(SimulatorExitedException.class)
                .hasMessage("The simulator did not start: The simulator is not running: simulator exited with code 1; "
                        + "its last words: ModuleNotFoundError: No module named pymunk.");
    }
}
