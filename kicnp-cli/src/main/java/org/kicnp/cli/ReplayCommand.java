package org.kicnp.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.kicnp.cli.scenario.ScenarioFiles;
import org.kicnp.cli.scenario.Table5Checks;
import org.kicnp.cli.scenario.Table5Run;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code kicnp replay scenarios/table5}: plays Table 5 headless — the platform on a copy of the knowledge base,
 * the simulator at accelerated time, the four robot agents, a scripted User A — prints every line and action as
 * it happens, checks the run and prints the stimulus-to-command latency.
 */
@Command(name = "replay", mixinStandardHelpOptions = true,
        description = "Play the Table 5 scenario headless with a scripted User A, check it, print latencies.")
public final class ReplayCommand implements Callable<Integer> {
    @Parameters(index = "0", arity = "0..1", paramLabel = "KB_DIR", description = "The scenario's knowledge base (default scenarios/table5); it is copied, never changed.")
    Path kbDir;

    @Option(names = "--time-scale", defaultValue = "8", description = "Simulator speed-up. Default: ${DEFAULT-VALUE}.")
    double timeScale;

    @Option(names = "--seed", defaultValue = "2004", description = "Simulator seed. Default: ${DEFAULT-VALUE}.")
    long seed;

    @Option(names = "--name", defaultValue = "Taro", description = "User A's name. Default: ${DEFAULT-VALUE}.")
    String name;

    @Option(names = "--drink", defaultValue = "Tea, please.", description = "User A's answer to the drink question (default: \"${DEFAULT-VALUE}\")")
    String drink;

    @Option(names = "--no-second-visit", description = "Do not play User A's second visit (greeted by name).")
    boolean noSecondVisit;

    @Override public Integer call() throws Exception {
        Path source = kbDir != null ? kbDir : ScenarioFiles.table5();
        Path work = Files.createTempDirectory("kicnp-replay-");
        Path kb = ScenarioFiles.copy(source, work.resolve("kb"));
        System.out.println("Replaying Table 5 from " + source + " (working copy " + kb + ", time x" + timeScale + ").");
        try (Table5Run run = Table5Run.headless(kb, seed, timeScale, Optional.of(System.out))) {
            run.playFirstVisit(name, drink);
            run.awaitEnd();
            List<String> problems = Table5Checks.problems(run.record(), name);
            if (!noSecondVisit) {
                run.playSecondVisit(name);
            }
            System.out.println();
            System.out.println(run.record().latencySummary());
            Table5Checks.syncSkewMillis(run.record()).ifPresent(ms -> System.out.println(
                    "synchronized start skew " + ms + " ms (allowed " + Table5Checks.SKEW_MS + ")"));
            System.out.println("event log: " + run.platform().events().file());
            if (problems.isEmpty()) {
                System.out.println("Table 5 replayed: every row in order, every action ended, succession, "
                        + "synchronization and restriction held.");
                return 0;
            }
            problems.forEach(p -> System.err.println("replay: " + p));
            return 1;
        }
    }
}
