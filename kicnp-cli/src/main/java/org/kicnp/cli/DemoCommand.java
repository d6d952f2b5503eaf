package org.kicnp.cli;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicBoolean;
import org.kicnp.cli.platform.PlatformConfig;
import org.kicnp.cli.scenario.ScenarioFiles;
import org.kicnp.cli.scenario.Table5Checks;
import org.kicnp.cli.scenario.Table5Run;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code kicnp demo}: the platform, the simulated room with Robovie, PINO, Scout and AIBO, and you as User A at the
 * terminal. {@code --auto} lets a scripted User A play Table 5 and exits 0 when it went as the paper tells it.
 * SIGTERM or Ctrl-C stops the simulator and the servers cleanly (a shutdown hook closes the run).
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = "Play User A of the paper's Table 5 at the terminal (or --auto) with the four simulated robots.")
public final class DemoCommand implements Callable<Integer> {
    @Option(names = "--auto", description = "A scripted User A plays Table 5; exit 0 when it went right.")
    boolean auto;

    @Option(names = "--kb", paramLabel = "DIR", description = "Knowledge-base directory. Default: ~/.kicnp/demo-kb "
            + "(a copy of scenarios/table5, kept between demos so the robots remember you); --auto uses a fresh copy.")
    Path kb;

    @Option(names = "--http-port", defaultValue = "8080", description = "Editor port. Default: ${DEFAULT-VALUE}.")
    int httpPort;

    @Option(names = "--time-scale", defaultValue = "2", description = "Simulator speed-up. Default: ${DEFAULT-VALUE} (--auto: 8).")
    double timeScale;

    @Option(names = "--name", defaultValue = "Taro", description = "User A's name with --auto. Default: ${DEFAULT-VALUE}.")
    String name;

    @Override public Integer call() throws Exception {
        Path dir = kb != null ? kb : auto ? Files.createTempDirectory("kicnp-demo-").resolve("kb")
                : Path.of(System.getProperty("user.home"), ".kicnp", "demo-kb");
        if (!Files.isDirectory(dir)) {
            ScenarioFiles.copy(ScenarioFiles.table5(), dir);
        }
        double scale = auto && timeScale == 2 ? 8 : timeScale;
        PlatformConfig config = PlatformConfig.of(dir).withGatewayPort(0).withHttpPort(Optional.of(httpPort));
        Table5Run run = Table5Run.start(config, 2004, scale, Optional.of(System.out));
        AtomicBoolean said = new AtomicBoolean();
        Runnable stop = () -> {
            run.close(); // a second caller waits until the first has closed the run
            if (said.compareAndSet(false, true)) {
                System.out.println("Demo stopped: the simulator and the servers are shut down.");
                System.out.flush();
            }
        };
        // On SIGTERM or Ctrl-C the JVM runs its hooks and then halts, whatever other threads are doing: without this
        // hook the simulator subprocess and the servers would be cut off (the knowledge store not closed). The signal
        // may also end the read of the terminal, so this thread closes the run too; the hook then waits for it.
        Thread hook = new Thread(stop, "kicnp-demo-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            ServeCommand.printBanner(run.platform());
            return auto ? playAuto(run) : playByHand(run);
        } finally {
            stop.run(); // before the hook goes, so a shutdown that starts meanwhile still waits for the close
            removeHook(hook);
        }
    }

    private static void removeHook(Thread hook) {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // Shutting down already: the hook is running and waits for the close.
        }
    }

    private int playAuto(Table5Run run) throws Exception {
        run.playFirstVisit(name, "Tea, please.");
        run.awaitEnd();
        System.out.println(run.record().latencySummary());
        List<String> problems = Table5Checks.problems(run.record(), name);
        problems.forEach(p -> System.err.println("demo: " + p));
        System.out.println(problems.isEmpty() ? "Table 5 played to the end." : "Table 5 did not go as in the paper.");
        return problems.isEmpty() ? 0 : 1;
    }

    private int playByHand(Table5Run run) throws Exception {
        System.out.println();
        System.out.println("You are User A. Type /come to walk up to Robovie, then answer what the robots ask");
        System.out.println("(\"My name is ...\", \"Tea, please.\"). /leave walks out, /quit ends the demo.");
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        for (String line = in.readLine(); line != null; line = in.readLine()) {
            String text = line.strip();
            switch (text) {
                case "" -> { }
                case "/come" -> run.user().appear();
                case "/leave" -> run.user().leave();
                case "/quit" -> {
                    return 0;
                }
                default -> {
                    int before = run.user().sayAgainReplies().size();
                    run.user().say(text);
                    Thread.sleep(400);
                    List<String> replies = run.user().sayAgainReplies();
                    replies.subList(before, replies.size()).forEach(r -> System.out.println("(parser) " + r));
                }
            }
        }
        return 0;
    }
}
