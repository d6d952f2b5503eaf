package org.kicnp.cli.platform;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.cli.scenario.RobotWorld;
import org.kicnp.cli.scenario.ScenarioFiles;
import org.kicnp.core.Value;
import org.kicnp.editor.Subscription;
import org.kicnp.editor.WorldSnapshot;
import org.kicnp.robots.SimOptions;
import org.kicnp.robots.SimWorld;

/**
 * The editor's World panel over the real simulator (a subprocess in manual mode): empty until the simulator is
 * attached, then the streamed states arrive as snapshots, and {@code GET /api/world} of the platform's editor
 * answers with them.
 */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class LiveWorldViewTest {
    @TempDir
    Path tmp;

    @Test
    void attach_toARunningSimulator_streamsSnapshotsWithTheFourRobots() throws Exception {
        LiveWorldView view = new LiveWorldView();
        assertThat(view.latest()).isEmpty();
        try (SimWorld sim = SimWorld.start(SimOptions.defaults().withManual(true))) {
            LinkedBlockingQueue<WorldSnapshot> seen = new LinkedBlockingQueue<>();
            try (Subscription s = view.onSnapshot(seen::add); AutoCloseable a = view.attach(sim)) {
                sim.step(1.0, false);

                WorldSnapshot first = seen.poll(20, TimeUnit.SECONDS);
                assertThat(first).isNotNull();
                assertThat(first.robots()).extracting(WorldSnapshot.Robot::name)
                        .containsExactlyInAnyOrder("robovie", "pino", "scout", "aibo");
                WorldSnapshot second = seen.poll(20, TimeUnit.SECONDS);
                assertThat(second).isNotNull();
                assertThat(second.time()).as("streamed every 200 ms of simulated time").isGreaterThan(first.time());
                assertThat(view.latest()).isPresent();
            }
        }
    }

    @Test
    void aRunningAction_isShownUnderItsCommandId_soTheEditorCanStopOrJudgeIt() throws Exception {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        try (Platform platform = Platform.start(PlatformConfig.of(kb).withEphemeralPorts());
             RobotWorld world = RobotWorld.start(platform, 7, 1.0)) {
            String go = platform.teleOperation().send("scout", "go_to", Map.of("x", "1.0", "y", "1.0"));

            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (!scoutRuns(platform, go) && System.nanoTime() < deadline) {
                Thread.sleep(50);
            }
            assertThat(scoutRuns(platform, go)).as("scout's go_to shown as '" + go + "' in the world").isTrue();
            platform.teleOperation().markWrong(go, "not there");
            platform.teleOperation().stop(go, "enough");
            while (scoutRuns(platform, go) && System.nanoTime() < deadline) {
                Thread.sleep(50);
            }
            assertThat(scoutRuns(platform, go)).as("scout halted").isFalse();
            assertThat(platform.kb().value("WrongAction-" + go, "reason")).contains(Value.of("not there"));
        }
    }

    private static boolean scoutRuns(Platform platform, String commandId) {
        return platform.world().latest().stream().flatMap(w -> w.robots().stream())
                .filter(r -> r.name().equals("scout")).flatMap(r -> r.actions().stream())
                .anyMatch(a -> a.id().equals(commandId) && a.action().equals("go_to"));
    }

    @Test
    void platformEditor_world_is204BeforeTheSimulator_thenItsLatestSnapshot() throws Exception {
        Path kb = ScenarioFiles.copy(ScenarioFiles.table5(), tmp.resolve("kb"));
        try (Platform platform = Platform.start(PlatformConfig.of(kb).withHttpPort(Optional.of(0)).withEphemeralPorts())) {
            HttpClient http = HttpClient.newHttpClient();
            HttpRequest get = HttpRequest.newBuilder(URI.create("http://127.0.0.1:"
                    + platform.editorPort().orElseThrow() + "/api/world")).GET().build();
            assertThat(http.send(get, HttpResponse.BodyHandlers.ofString()).statusCode()).isEqualTo(204);

            try (SimWorld sim = SimWorld.start(SimOptions.defaults().withManual(true));
                 AutoCloseable a = platform.world().attach(sim)) {
                sim.step(1.0, false);
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
                while (platform.world().latest().isEmpty() && System.nanoTime() < deadline) {
                    Thread.sleep(50);
                }

                HttpResponse<String> r = http.send(get, HttpResponse.BodyHandlers.ofString());
                assertThat(r.statusCode()).isEqualTo(200);
                JsonNode world = new ObjectMapper().readTree(r.body());
                assertThat(world.path("robots")).extracting(n -> n.path("name").asText())
                        .containsExactlyInAnyOrder("robovie", "pino", "scout", "aibo");
            }
        }
    }
}
