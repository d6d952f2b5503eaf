package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class MainTest {

    @Test
    void help_listsEveryVerbIncludingTheLauncherOnes() {
        CliRun run = CliRun.of("--help");

        assertThat(run.exitCode()).isZero();
        assertThat(run.out()).contains("Usage: kicnp").contains("validate").contains("bench").contains("test");
    }

    @Test
    void noVerb_printsUsageAndSucceeds() {
        CliRun run = CliRun.of();

        assertThat(run.exitCode()).isZero();
        assertThat(run.out()).contains("Usage: kicnp");
    }

    @Test
    void test_whenRunOutsideTheLauncher_pointsAtTheLauncher() {
        CliRun run = CliRun.of("test");

        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("./kicnp test");
    }

    @Test
    void unknownVerb_failsWithUsageError() {
        CliRun run = CliRun.of("frobnicate");

        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("frobnicate");
    }
}
