package org.kicnp.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The {@code ./kicnp} command: one entry point for people and scripts. Each verb is a class of its own in this
 * package, listed in {@code subcommands} below; every verb answers {@code --help}.
 */
@Command(name = "kicnp",
        mixinStandardHelpOptions = true,
        versionProvider = Main.Version.class,
        description = "K-ICNP: a multi-robot management platform on a frame knowledge base.",
        subcommands = {
            CommandLine.HelpCommand.class,
            ValidateCommand.class,
            RobotsCommand.class,
            InferCommand.class,
            BenchCommand.class,
            TestCommand.class,
            ServeCommand.class,
            ReplayCommand.class,
            DemoCommand.class,
            AgentCommand.class,
        })
public final class Main implements Runnable {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    public static void main(String[] args) {
        System.exit(run(args));
    }

    /** Runs the command line and returns its exit code, without exiting: tests call this. */
    public static int run(String... args) {
        return commandLine().execute(args);
    }

    /** The command line as {@link #run} executes it; tests give it writers of their own to run verbs side by side. */
    static CommandLine commandLine() {
        return new CommandLine(new Main()).setCaseInsensitiveEnumValuesAllowed(true)
                .setExecutionExceptionHandler(new CommandFailure());
    }

    @Override public void run() {
        spec.commandLine().usage(System.out);
    }

    /** Reports the version recorded in the jar's manifest, or "development" when run from classes. */
    static final class Version implements CommandLine.IVersionProvider {
        @Override public String[] getVersion() {
            String v = Main.class.getPackage().getImplementationVersion();
            return new String[] {"kicnp " + (v == null ? "development" : v)};
        }
    }
}
