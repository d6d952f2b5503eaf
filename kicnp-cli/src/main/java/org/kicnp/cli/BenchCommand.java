package org.kicnp.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code kicnp bench}: listed here so that {@code ./kicnp --help} shows it, but run by the {@code ./kicnp}
 * launcher from the kicnp-bench module, whose peer engines (such as Drools) must never be on this module's
 * class path.
 */
@Command(name = "bench",
        mixinStandardHelpOptions = true,
        description = {
            "Runs a benchmark (e.g. 'core': load, save, heap and query cost of a large knowledge base).",
            "Handled by the ./kicnp launcher from kicnp-bench; see ./kicnp bench --help."
        })
public final class BenchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Override public Integer call() {
        spec.commandLine().getErr().println("The 'bench' verb is run by the launcher: use ./kicnp bench --help.");
        return 2;
    }
}
