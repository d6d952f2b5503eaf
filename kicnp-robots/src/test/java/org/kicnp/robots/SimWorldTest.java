package org.kicnp.robots;

import com.fasterxml.jackson.databind.JsonNode;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

/** The real simulator as a subprocess: requests, commands, events, errors, and its death. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class SimWorldTest {
    static SimOptions manual() {
        return SimOptions.defaults().withManual(true);
    }

    @Test
    void start_inManualMode_saysHelloWithTheFourRobots() {
        try (SimWorld world = SimWorld.start(manual().withSeed(7))) {
            assertThat(world.hello().protocol()).isEqualTo("kicnp-sim/1");
            assertThat(world.hello().seed()).isEqualTo(7);
            assertThat(world.hello().mode()).isEqualTo("manual");
            assertThat(world.hello().robots().fieldNames()).toIterable()
                    .containsExactlyInAnyOrder("robovie", "pino", "scout", "aibo");
            assertThat(world.alive()).isTrue();
        }
    }

    @Test
    void command_scoutGoTo_startsArrivesAndEndsInOrder() throws Exception {
        try (SimWorld world = SimWorld.start(manual())) {
            List<String> seen = new CopyOnWriteArrayList<>();
            world.addListener(e -> {
                if (e instanceof SimEvent.Arrival a) {
                    seen.add("arrival " + a.robot());
                }
            });
            List<ActionUpdate> updates = new CopyOnWriteArrayList<>();
            SimAction go = world.command(SimRequest.Command.of("scout", "go_to", Map.of("x", 6.2, "y", 3.0)), updates::add);
            world.step(10, true);

            ActionUpdate outcome = go.outcome().get(5, TimeUnit.SECONDS);
            assertThat(outcome).isInstanceOf(ActionUpdate.Ended.class);
            assertThat(((ActionUpdate.Ended) outcome).result().get("y").asDouble()).isBetween(2.9, 3.1);
            assertThat(updates).hasSize(2).first().isInstanceOf(ActionUpdate.Started.class);
            assertThat(go.started()).isTrue();
            assertThat(seen).containsExactly("arrival scout");
        }
    }

    @Test
    void command_scoutBlockedByAnObstacle_failsWithTheBumperReason() throws Exception {
        try (SimWorld world = SimWorld.start(manual())) {
            world.call(new SimRequest.AddObstacle("box", 6.2, 3.0, 1.0, 0.2));
            SimAction go = world.command(SimRequest.Command.of("scout", "go_to", Map.of("x", 6.2, "y", 4.5)));
            world.step(15, true);

            assertThat(go.outcome().get(5, TimeUnit.SECONDS))
                    .isEqualTo(new ActionUpdate.Failed(((ActionUpdate.Failed) go.outcome().get()).t(), "blocked: bumper 0"));
        }
    }

    @Test
    void command_whenThePartIsBusy_failsWithTheSimulatorsRefusalAndNeverStarts() throws Exception {
        try (SimWorld world = SimWorld.start(manual())) {
            SimAction first = world.command(SimRequest.Command.of("scout", "go_to", Map.of("x", 6.2, "y", 3.0)));
            SimAction second = world.command(SimRequest.Command.of("scout", "turn_to", Map.of("heading_deg", 0)));

            ActionUpdate refused = second.outcome().get(5, TimeUnit.SECONDS);
            assertThat(refused).isInstanceOf(ActionUpdate.Failed.class);
            assertThat(((ActionUpdate.Failed) refused).reason()).contains("base is busy with go_to '" + first.id() + "'");
            assertThat(second.started()).isFalse();
        }
    }

    @Test
    void request_withAPositionOutsideTheRoom_isRejectedNamingTheField() {
        try (SimWorld world = SimWorld.start(manual())) {
            assertThatThrownBy(() -> world.call(new SimRequest.PlaceRobot("aibo", 50, 1, 0)))
                    .isInstanceOf(SimRequestRejectedException.class)
                    .hasMessageContaining("'x'")
                    .satisfies(e -> assertThat(((SimRequestRejectedException) e).field()).contains("x"));
            assertThat(world.alive()).isTrue();
        }
    }

    @Test
    void query_returnsTheStateOfTheRobotsAndCups() {
        try (SimWorld world = SimWorld.start(manual())) {
            JsonNode state = world.query();
            assertThat(state.at("/robots/aibo/posture").asText()).isEqualTo("stand");
            assertThat(state.at("/cups/tea-1/kind").asText()).isEqualTo("tea");
        }
    }

    @Test
    void kill9_midAction_failsTheActionWithTheExitCodeAndLaterCallsFailFast() throws Exception {
        try (SimWorld world = SimWorld.start(SimOptions.defaults().withTimeScale(1))) {
            List<SimEvent> exits = new CopyOnWriteArrayList<>();
            world.addListener(e -> {
                if (e instanceof SimEvent.Exited) {
                    exits.add(e);
                }
            });
            List<ActionUpdate> updates = new CopyOnWriteArrayList<>();
            SimAction go = world.command(SimRequest.Command.of("scout", "go_to", Map.of("x", 1.0, "y", 1.0)), updates::add);
            waitUntil(go::started);

            kill9(world.pid());

            ActionUpdate outcome = go.outcome().get(10, TimeUnit.SECONDS);
            assertThat(outcome).isInstanceOf(ActionUpdate.Failed.class);
            assertThat(((ActionUpdate.Failed) outcome).reason()).startsWith("simulator exited with code 137");
            waitUntil(() -> !exits.isEmpty());
            assertThat(world.alive()).isFalse();
            assertThat(world.deathReason()).hasValueSatisfying(r -> assertThat(r).contains("code 137"));
            assertThatThrownBy(world::query)
                    .isInstanceOf(SimulatorExitedException.class)
                    .hasMessage("The simulator is not running: simulator exited with code 137 (signal 9).");
            assertThatThrownBy(() -> world.command(SimRequest.Command.of("aibo", "lie_down", Map.of())))
                    .isInstanceOf(SimulatorExitedException.class);
        }
    }

    @Test
    void close_thenARequest_failsFastSayingItWasShutDown() {
        SimWorld world = SimWorld.start(manual());
        world.close();

        assertThat(world.alive()).isFalse();
        assertThatThrownBy(world::query)
                .isInstanceOf(SimulatorExitedException.class)
                .hasMessage("The simulator is not running: simulator was shut down.");
    }

    @Test
    void start_withARepositoryWithoutTheSimulator_failsNamingTheFolder(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) {
        assertThatThrownBy(() -> SimWorld.start(manual().withRepoRoot(dir)))
                .isInstanceOf(SimulatorException.class)
                .hasMessage("No simulator under '" + dir.resolve("robots-sim") + "': expected robots-sim/kicnp_sim there.");
    }

    @Test
    void aHungSimulator_whoseInputPipeIsFull_blocksNeitherACommandNorClose() throws Exception {
        SimWorld world = SimWorld.start(SimOptions.defaults().withTimeScale(1).withRequestTimeout(Duration.ofSeconds(1)));
        try {
            signal("STOP", world.pid()); // alive but reading nothing: the pipe to it fills up
            String text = "x".repeat(200_000); // more than a pipe holds

            SimAction say = CompletableFuture.supplyAsync(() -> world.command(
                    SimRequest.Command.of("robovie", "say", Map.of("text", text)))).get(3, TimeUnit.SECONDS);
            ActionUpdate outcome = say.outcome().get(10, TimeUnit.SECONDS);
            assertThat(outcome).isInstanceOf(ActionUpdate.Failed.class);
            assertThat(((ActionUpdate.Failed) outcome).reason()).contains("within 1 s");

            CompletableFuture.runAsync(world::close).get(15, TimeUnit.SECONDS);
            assertThat(ProcessHandle.of(world.pid()).map(ProcessHandle::isAlive)).isNotEqualTo(Optional.of(true));
        } finally {
            signal("KILL", world.pid());
        }
    }

    @Test
    void aSimulatorThatHangsMidAction_isStoppedAndTheActionFailsSayingSo() throws Exception {
        SimWorld world = SimWorld.start(SimOptions.defaults().withTimeScale(1).withRequestTimeout(Duration.ofSeconds(1)));
        try {
            List<SimEvent> exits = new CopyOnWriteArrayList<>();
            world.addListener(e -> {
                if (e instanceof SimEvent.Exited) {
                    exits.add(e);
                }
            });
            SimAction go = world.command(SimRequest.Command.of("scout", "go_to", Map.of("x", 1.0, "y", 1.0)));
            waitUntil(go::started);

            signal("STOP", world.pid()); // the process lives on, but answers nothing and ends nothing

            ActionUpdate outcome = go.outcome().get(8, TimeUnit.SECONDS);
            assertThat(outcome).isInstanceOf(ActionUpdate.Failed.class);
            assertThat(((ActionUpdate.Failed) outcome).reason()).isEqualTo("simulator did not answer within 1 s and was stopped");
            waitUntil(() -> !exits.isEmpty());
            assertThat(world.alive()).isFalse();
            waitUntil(() -> ProcessHandle.of(world.pid()).map(ProcessHandle::isAlive).orElse(false) == false);
        } finally {
            signal("KILL", world.pid());
            world.close();
        }
    }

    @Test
    void options_withARequestTimeoutThatIsNotPositive_areRefused() {
        assertThatThrownBy(() -> SimOptions.defaults().withRequestTimeout(Duration.ZERO))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("The request timeout must be positive, not 0 ms.");
        assertThatThrownBy(() -> SimOptions.defaults().withRequestTimeout(Duration.ofSeconds(-1)))
                .isInstanceOf(IllegalArgumentException.class);
    }

    static void signal(String name, long pid) throws IOException, InterruptedException {
        new ProcessBuilder("kill", "-" + name, Long.toString(pid)).inheritIO().start().waitFor();
    }

    static void kill9(long pid) throws IOException, InterruptedException {
        Process kill = new ProcessBuilder("kill", "-9", Long.toString(pid)).inheritIO().start();
        assertThat(kill.waitFor()).isZero();
    }

    static void waitUntil(java.util.function.BooleanSupplier condition) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("Condition not met within 10 s.");
            }
            Thread.sleep(20);
        }
    }
}
