package org.kicnp.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code kicnp test}: listed here so that {@code ./kicnp --help} shows it, but run by the {@code ./kicnp}
 * launcher itself, because it drives Maven and the simulator's Python tests rather than Java code.
 */
@Command(name = "test",
        mixinStandardHelpOptions = true,
        description = {
            "Runs the whole test suite: ./mvnw -B verify, then the robots-sim Python tests.",
            "Handled by the ./kicnp launcher; see ./kicnp test --help."
        })
public final class TestCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Override public Integer call() {
        spec.commandLine().getErr().println("The 'test' verb is run by the launcher: use ./kicnp test.");
        return 2;
    }
}
