package org.kicnp.cli.scenario;

import java.io.PrintStream;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.concurrent.TimeoutException;
import org.kicnp.cli.platform.Platform;
import org.kicnp.cli.platform.PlatformConfig;

/**
 * One session of the Table 5 scenario: the platform on a knowledge-base directory (ephemeral ports unless told
 * otherwise), the simulated world with its four robots, User A, a {@link RunRecord} and, when given an output, a
 * {@link Narrator}. The scripted plays ({@link #playFirstVisit}, {@link #playSecondVisit}) are User A's part
 * only: the robots act on what the knowledge base decides.
 */
public final class Table5Run implements AutoCloseable {
    /** Time allowed for one step of the scenario, in scenario-time at the accelerated simulator. */
    public static final Duration STEP = Duration.ofSeconds(40);

    private final Platform platform;
    private final RobotWorld world;
    private final UserA user;
    private final RunRecord record = new RunRecord();
    private final Object closeLock = new Object();
    private boolean closed;

    private Table5Run(Platform platform, RobotWorld world, UserA user) {
        this.platform = platform;
        this.world = world;
        this.user = user;
    }

    public static Table5Run start(PlatformConfig config, long seed, double timeScale, Optional<PrintStream> out) {
        Platform platform = Platform.start(config);
        RobotWorld world = null;
        try {
            world = RobotWorld.start(platform, seed, timeScale);
            UserA user = UserA.connect(platform, world.sim(), "userA");
            Table5Run run = new Table5Run(platform, world, user);
            platform.events().subscribe(run.record);
            out.ifPresent(o -> platform.events().subscribe(new Narrator(o)));
            return run;
        } catch (RuntimeException e) {
            if (world != null) {
                world.close();
            }
            platform.close();
            throw e;
        }
    }

    /** On a knowledge-base directory, any free ports, no editor. */
    public static Table5Run headless(Path kbDir, long seed, double timeScale, Optional<PrintStream> out) {
        return headless(kbDir, Optional.empty(), seed, timeScale, out);
    }

    /** As {@link #headless(Path, long, double, Optional)}, writing the event log where told. */
    public static Table5Run headless(Path kbDir, Optional<Path> eventLog, long seed, double timeScale,
                                     Optional<PrintStream> out) {
        return start(PlatformConfig.of(kbDir).withEphemeralPorts().withHttpPort(Optional.empty()).withEventLog(eventLog),
                seed, timeScale, out);
    }

    public Platform platform() {
        return platform;
    }

    public RobotWorld world() {
        return world;
    }

    public UserA user() {
        return user;
    }

    public RunRecord record() {
        return record;
    }

    /**
     * User A's part of Table 5 on a first visit: appears, answers the name when asked, names a drink when asked.
     * Returns once Robovie has asked for the drink and it was answered.
     */
    public void playFirstVisit(String name, String drink) throws TimeoutException, InterruptedException {
        playUntilAskedForADrink(name);
        user.say(drink);
    }

    /** User A's part of Table 5 up to Robovie's "What do you want to drink?". */
    public void playUntilAskedForADrink(String name) throws TimeoutException, InterruptedException {
        user.appear();
        record.awaitLine("What is your name?", STEP);
        record.awaitFinished("AskUserName", STEP); // a person lets Robovie finish its question
        user.say("My name is " + name + ".");
        record.awaitLine("What do you want to drink?", STEP.multipliedBy(2));
        record.awaitFinished("AskDrink", STEP);
    }

    /** Waits until AIBO has lain down, or Robovie has said AIBO cannot come. */
    public void awaitEnd() throws TimeoutException, InterruptedException {
        record.await(e -> (e.kind().equals("feedback") && !e.text("stage").equals("started")
                        && record.step(e.text("id")).map(s -> s.frame().equals("AIBOAction2")).orElse(false))
                        || (e.kind().equals("utterance") && RunRecord.firstValue(e).contains("AIBO cannot")),
                STEP.multipliedBy(3), "the end of the scenario (AIBO lying down)");
    }

    /** Leaves, and comes back: Robovie should greet by name. */
    public void playSecondVisit(String name) throws TimeoutException, InterruptedException {
        user.leave();
        record.await(e -> e.kind().equals("retracted") && e.text("instance").equals("signal_robovie_face_seen"), STEP,
                "the end of the visit (FaceLost)");
        playReturn(name);
    }

    /**
     * User A, already known, comes in: Robovie should greet them by name. Returns once Robovie has finished saying so,
     * so that a run closed next does not cut its last action short (it was reported failed, "disconnected").
     */
    public void playReturn(String name) throws TimeoutException, InterruptedException {
        user.appear();
        record.awaitLine("Hi, " + name + ". Good to see you again.", STEP);
        record.awaitFinished("WelcomeBack", STEP);
    }

    /**
     * Stops User A, the simulator and the platform, once. A second caller waits until the first has finished: on
     * SIGTERM the command's own thread (whose read of the terminal the signal ends) and the shutdown hook both close
     * the run, and the JVM halts as soon as the hook returns.
     */
    @Override public void close() {
        synchronized (closeLock) {
            if (closed) {
                return;
            }
            closed = true;
            user.close();
            world.close();
            platform.close();
        }
    }
}
