package org.kicnp.robots;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kicnp.core.Value;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.kicnp.robots.SimWorldTest.kill9;
import static org.kicnp.robots.SimWorldTest.waitUntil;

/** Each robot's driver against the real simulator: platform command in, feedback and sensor signals out. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RobotDriverTest {
    private final List<SensorSignal> signals = new CopyOnWriteArrayList<>();
    private final List<Feedback> feedback = new CopyOnWriteArrayList<>();
    private SimWorld world;

    private RobotDriver driver(SimOptions options, RobotModel model) {
        world = SimWorld.start(options);
        return RobotDriver.attach(world, model, signals::add);
    }

    @AfterEach
    void stop() {
        if (world != null) {
            world.close();
        }
    }

    private Feedback run(RobotDriver d, String action, Map<String, String> args) throws Exception {
        CompletableFuture<Feedback> done = d.execute(action, args, feedback::add);
        if (world.alive() && !done.isDone()) {
            world.step(30, true);
        }
        return done.get(10, TimeUnit.SECONDS);
    }

    private List<SensorSignal> signals(String sensor) {
        return signals.stream().filter(s -> s.sensor().equals(sensor)).toList();
    }

    @Test
    void scoutGoTo_reportsStartedProgressAndEndedWithTheArrival() throws Exception {
        RobotDriver scout = driver(SimWorldTest.manual(), RobotModels.scout());

        Feedback end = run(scout, "ScoutGoTo", Map.of("x", "6.2", "y", "4.5"));

        assertThat(end).isInstanceOf(Feedback.Ended.class);
        assertThat(((Feedback.Ended) end).result()).contains("\"distance_error_m\"");
        assertThat(feedback.getFirst()).isEqualTo(new Feedback.Started());
        assertThat(feedback).filteredOn(f -> f instanceof Feedback.Progress).isNotEmpty()
                .allSatisfy(f -> assertThat(((Feedback.Progress) f).fraction()).isBetween(0.0, 1.0));
        assertThat(signals("arrival")).singleElement()
                .satisfies(s -> assertThat(s.values().get(2)).isInstanceOfSatisfying(Value.Real.class,
                        y -> assertThat(y.value()).isBetween(4.4, 4.6)));
    }

    @Test
    void robovieSay_endsWithTheTextAndProducesAnUtterance() throws Exception {
        RobotDriver robovie = driver(SimWorldTest.manual(), RobotModels.robovie());

        Feedback end = run(robovie, "RobovieSay", Map.of("text", "How are you!"));

        assertThat(end).isInstanceOf(Feedback.Ended.class);
        assertThat(((Feedback.Ended) end).result()).contains("\"text\":\"How are you!\"");
        assertThat(signals("utterance")).singleElement()
                .satisfies(s -> assertThat(s.first()).isEqualTo(Value.of("How are you!")));
    }

    @Test
    void pinoWalksToAUserAndShakesHands() throws Exception {
        RobotDriver pino = driver(SimWorldTest.manual(), RobotModels.pino());
        world.call(new SimRequest.SpawnUser("alice", 4.0, 2.0, 90, Optional.empty()));

        assertThat(run(pino, "PinoApproachUser", Map.of("user", "alice"))).isInstanceOf(Feedback.Ended.class);
        Feedback shake = run(pino, "PinoShakeHands", Map.of("user", "alice"));

        assertThat(shake).isInstanceOf(Feedback.Ended.class);
        assertThat(((Feedback.Ended) shake).result()).contains("\"user\":\"alice\"");
        assertThat(signals("arrival")).singleElement().satisfies(s -> assertThat(s.first()).isEqualTo(Value.of("alice")));
    }

    @Test
    void approachUser_progressGoesTowardsTheAskedDistance_notTowardsTouchingTheUser() throws Exception {
        RobotDriver scout = driver(SimWorldTest.manual(), RobotModels.scout());
        world.call(new SimRequest.SpawnUser("alice", 6.2, 5.0, -90, Optional.empty())); // 2.55 m north of Scout

        Feedback end = run(scout, "ScoutApproachUser", Map.of("user", "alice", "distance_m", "1.0"));

        assertThat(end).isInstanceOf(Feedback.Ended.class);
        List<Double> fractions = feedback.stream().filter(f -> f instanceof Feedback.Progress)
                .map(f -> ((Feedback.Progress) f).fraction()).toList();
        assertThat(fractions).hasSizeGreaterThan(2).isSorted();
        assertThat(fractions.getLast()).as("progress in %s", fractions).isGreaterThan(0.85);
    }

    @Test
    void aiboLieDown_endsLyingDown() throws Exception {
        RobotDriver aibo = driver(SimWorldTest.manual(), RobotModels.aibo());

        Feedback end = run(aibo, "AiboLieDown", Map.of());

        assertThat(end).isEqualTo(new Feedback.Ended("{\"posture\":\"lie_down\",\"duration_s\":1.5}"));
        assertThat(world.query().at("/robots/aibo/posture").asText()).isEqualTo("lie_down");
    }

    @Test
    void scoutBlockedByAnObstacle_failsWithTheSimulatorsReasonAndABumperSignal() throws Exception {
        RobotDriver scout = driver(SimWorldTest.manual(), RobotModels.scout());
        world.call(new SimRequest.AddObstacle("box", 6.2, 3.0, 1.0, 0.2));

        Feedback end = run(scout, "go_to", Map.of("x", "6.2", "y", "4.5"));

        assertThat(end).isEqualTo(new Feedback.Failed("blocked: bumper 0"));
        assertThat(feedback.getFirst()).isEqualTo(new Feedback.Started());
        assertThat(signals("bumper")).first().satisfies(s -> assertThat(s.values())
                .containsExactly(Value.of(true), Value.of(0), Value.of("box")));
    }

    @Test
    void aBadArgument_failsWithoutStartingAndSaysWhich() throws Exception {
        RobotDriver scout = driver(SimWorldTest.manual(), RobotModels.scout());

        Feedback end = run(scout, "ScoutGoTo", Map.of("x", "far", "y", "1"));

        assertThat(end).isEqualTo(new Feedback.Failed("Argument 'x' of ScoutGoTo must be a number, not 'far'."));
        assertThat(feedback).containsExactly(end);
    }

    @Test
    void aSayTooLongForTheProtocolsLineLimit_failsWithoutStartingAndSaysWhy_andTheRobotSpeaksOn() throws Exception {
        RobotDriver robovie = driver(SimWorldTest.manual(), RobotModels.robovie());

        Feedback end = run(robovie, "RobovieSay", Map.of("text", "x".repeat(10_000_000)));

        assertThat(end).isInstanceOfSatisfying(Feedback.Failed.class, f -> assertThat(f.reason())
                .contains("would be a line of 100000").contains("characters, longer than the protocol's limit of "
                        + "10000000 characters; it was not sent."));
        assertThat(feedback).containsExactly(end);
        assertThat(run(robovie, "RobovieSay", Map.of("text", "Hello."))).isInstanceOf(Feedback.Ended.class);
    }

    @Test
    void anUnknownAction_failsNamingTheRobotsActions() throws Exception {
        RobotDriver aibo = driver(SimWorldTest.manual(), RobotModels.aibo());

        Feedback end = run(aibo, "AiboFly", Map.of());

        assertThat(end).isInstanceOfSatisfying(Feedback.Failed.class, f -> assertThat(f.reason())
                .startsWith("Robot 'aibo' has no action 'AiboFly'; it offers [AiboGoTo,"));
    }

    @Test
    void simulatorKilledMidAction_failsTheActionSaysSoAndFailsLaterCommandsFast() throws Exception {
        RobotDriver scout = driver(SimOptions.defaults().withTimeScale(1), RobotModels.scout());
        CompletableFuture<Feedback> done = scout.execute("ScoutGoTo", Map.of("x", "1", "y", "1"), feedback::add);
        waitUntil(() -> !feedback.isEmpty());
        assertThat(feedback.getFirst()).isEqualTo(new Feedback.Started());

        kill9(world.pid());

        assertThat(done.get(10, TimeUnit.SECONDS)).isEqualTo(new Feedback.Failed("simulator exited with code 137 (signal 9)"));
        waitUntil(() -> !signals("simulator").isEmpty());
        assertThat(signals("simulator").getFirst().values())
                .containsExactly(Value.of("exited"), Value.of("simulator exited with code 137 (signal 9)"));
        assertThat(scout.alive()).isFalse();
        long before = System.nanoTime();
        Feedback late = scout.execute("ScoutTurnTo", Map.of("heading_deg", "0"), f -> { }).get(1, TimeUnit.SECONDS);
        assertThat(late).isEqualTo(new Feedback.Failed("simulator exited with code 137 (signal 9)"));
        assertThat(System.nanoTime() - before).isLessThan(TimeUnit.MILLISECONDS.toNanos(500));
    }
}
