package org.kicnp.bench;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * {@code ./kicnp bench}: the benchmarks, one sub-command each. Run by the launcher from this module's own class
 * path, apart from the command line's, so peer engines used for comparison never reach the platform at run time.
 */
@Command(name = "kicnp bench",
        mixinStandardHelpOptions = true,
        description = "Benchmarks of the K-ICNP platform. Each prints a table, then one JSON object as its last line.",
        subcommands = {
            CommandLine.HelpCommand.class,
            CoreBench.class,
            GatewayRelayCommand.class,
            GatewayBenchCommand.class,
        })
public final class BenchMain implements Runnable {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    public static void main(String[] args) {
        System.exit(run(args));
    }

    /** Runs the benchmark command line and returns its exit code, without exiting: tests call this. */
    public static int run(String... args) {
        return new CommandLine(new BenchMain()).execute(args);
    }

    @Override public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }
}
