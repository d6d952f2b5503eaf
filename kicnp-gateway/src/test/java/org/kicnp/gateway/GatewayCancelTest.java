package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kicnp.agent.ActionFailedException;
import org.kicnp.agent.ActionHandle;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.CommandTicket;
import org.kicnp.agent.RequestRefusedException;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Message.Command;

/** Cancelling a command in flight, over real sockets: a user agent, the platform's ActionSink, refusals. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class GatewayCancelTest {
    private static final Duration WAIT = Duration.ofSeconds(10);

    private final List<String> heard = new CopyOnWriteArrayList<>();
    private final List<AutoCloseable> open = new ArrayList<>();
    private GatewayServer server;

    /** A robot whose commands run until cancelled; it finishes each one after the cancel, as a slow robot would. */
    static final class SlowRobot extends AgentBase {
        final CountDownLatch running = new CountDownLatch(1);
        final List<String> lateReports = new CopyOnWriteArrayList<>();
        private final boolean stopsItself;

        SlowRobot(AgentOptions options, boolean stopsItself) {
            super(options);
            this.stopsItself = stopsItself;
        }

        @Override protected void onCommand(Command command, ActionHandle handle) {
            handle.started();
            running.countDown();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (!handle.isCancelRequested() && System.nanoTime() < deadline) {
                pause();
            }
            // The robot's own program winds down and reports, after the cancel was already answered: ignored.
            try {
                Thread.sleep(200);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            handle.ended("walked all the way");
            lateReports.add("ended after " + handle.cancelReason().orElse("no cancel"));
        }

        @Override protected void onCancel(ActionHandle handle, String reason) {
            if (stopsItself) {
                handle.failed("stopped on the spot: " + reason);
            } else {
                super.onCancel(handle, reason);
            }
        }
    }

    @BeforeEach
    void start() {
        AgentDirectory agents = AgentDirectory.empty()
                .with("scout", "scout-token", AgentKind.ROBOT)
                .with("alice", "alice-token", AgentKind.USER)
                .with("bob", "bob-token", AgentKind.USER);
        server = GatewayServer.start(GatewayConfig.defaults().withPort(0), agents, KnowledgeBase.create(),
                new GatewayEndToEndTest.Recorder(heard));
    }

    @AfterEach
    void stop() throws Exception {
        for (AutoCloseable c : open.reversed()) {
            c.close();
        }
        server.close();
    }

    private <A extends AgentBase> A connect(A agent) {
        open.add(agent);
        agent.startAndAwait(WAIT);
        return agent;
    }

    private AgentOptions options(String name, AgentKind kind) {
        return AgentOptions.of("127.0.0.1", server.port(), name, kind, name + "-token");
    }

    @Test
    void aMalformedCancel_getsBadMessage_andOnlyItsConnectionCloses() throws Exception {
        SlowRobot scout = connect(new SlowRobot(options("scout", AgentKind.ROBOT), false));
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));
        CommandTicket walk = alice.command("scout", "walk", Map.of());
        assertThat(scout.running.await(10, TimeUnit.SECONDS)).isTrue();

        for (String json : List.of(
                // a number where the protocol wants a string: the command id, the robot, the reason
                "{\"v\":1,\"type\":\"cancel\",\"id\":\"1\",\"robot\":\"scout\",\"command\":7,\"reason\":\"r\"}",
                "{\"v\":1,\"type\":\"cancel\",\"id\":\"1\",\"robot\":\"scout\",\"command\":\"" + walk.command().id()
                        + "\",\"reason\":false}",
                "{\"v\":1,\"type\":\"cancel\",\"id\":\"1\",\"robot\":\"scout\",\"command\":\"" + walk.command().id()
                        + "\"}")) {
            try (RawClient raw = new RawClient(server.port())) {
                raw.send(new org.kicnp.protocol.Message.Hello("h", "bob", AgentKind.USER, "bob-token"));
                assertThat(raw.read()).isInstanceOf(org.kicnp.protocol.Message.AuthResult.class);
                raw.sendPayload(json.getBytes(java.nio.charset.StandardCharsets.UTF_8));
                assertThat(raw.readUntilClosed()).as(json).singleElement()
                        .isInstanceOfSatisfying(org.kicnp.protocol.Message.ErrorReply.class,
                                e -> assertThat(e.code()).isEqualTo(ErrorCode.BAD_MESSAGE));
            }
        }

        // Nothing was cancelled, and the other connections carry on.
        assertThat(walk.feedback()).extracting(f -> f.stage().name()).containsExactly("STARTED");
        assertThat(alice.isConnected() && scout.isConnected()).isTrue();
        alice.cancel("scout", walk.command().id(), "done testing");
        assertThatThrownBy(() -> walk.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessage("cancelled: done testing (asked by 'alice')");
    }

    @Test
    void aRobotWhoseOnCancelReportsTheEnd_mayStillReportFromItsProgram_withoutBeingThrownAt() throws Exception {
        List<String> program = new CopyOnWriteArrayList<>();
        CountDownLatch running = new CountDownLatch(1);
        connect(new AgentBase(options("scout", AgentKind.ROBOT)) {
            @Override protected void onCommand(Command command, ActionHandle handle) {
                handle.started();
                running.countDown();
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
                while (!handle.isDone() && System.nanoTime() < deadline) {
                    try {
                        Thread.sleep(5); // a step of the robot's program; sleeping holds no carrier thread
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        return;
                    }
                }
                // The program notices only at its next step, and reports it as it always does.
                try {
                    handle.progress(0.5, "half way");
                    handle.ended("walked");
                    program.add("reported");
                } catch (RuntimeException e) {
                    program.add("thrown at: " + e.getMessage());
                }
            }

            @Override protected void onCancel(ActionHandle handle, String reason) {
                handle.failed("braked: " + reason);
            }
        });
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));
        CommandTicket walk = alice.command("scout", "walk", Map.of());
        assertThat(running.await(10, TimeUnit.SECONDS)).isTrue();

        alice.cancel("scout", walk.command().id(), "stop");

        assertThatThrownBy(() -> walk.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessage("braked: stop (asked by 'alice')");
        Eventually.await("the robot's program wound down", () -> !program.isEmpty());
        assertThat(program).containsExactly("reported");
        assertThat(walk.feedback()).extracting(f -> f.stage().name()).containsExactly("STARTED", "FAILED");
    }

    @Test
    void aRobotWhoseOnCancelThrows_failsTheCommandSayingTheCancelFailed_andKeepsItsConnection() throws Exception {
        CountDownLatch running = new CountDownLatch(1);
        AgentBase scout = connect(new AgentBase(options("scout", AgentKind.ROBOT)) {
            @Override protected void onCommand(Command command, ActionHandle handle) {
                handle.started(); // the robot works on it elsewhere and reports later
                running.countDown();
            }

            @Override protected void onCancel(ActionHandle handle, String reason) {
                throw new IllegalStateException("the brake does not answer");
            }
        });
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));
        CommandTicket walk = alice.command("scout", "walk", Map.of());
        assertThat(running.await(10, TimeUnit.SECONDS)).isTrue();

        alice.cancel("scout", walk.command().id(), "stop");

        // Not "cancelled": the robot may still be moving, and whoever asked must know.
        assertThatThrownBy(() -> walk.result(Duration.ofSeconds(5))).isInstanceOf(ActionFailedException.class)
                .hasMessage("cancel failed: the brake does not answer (agent 'scout', asked to stop: stop (asked by "
                        + "'alice')); the robot may not have stopped");
        Eventually.await("the command is no longer in flight", () -> server.commandsInFlight() == 0);
        assertThat(scout.commandsInFlight()).isZero();
        assertThat(scout.isConnected()).isTrue();
    }

    @Test
    void theGatewayGoingAway_cancelsTheRobotsCommandsInFlight_andIgnoresTheirLaterReports() throws Exception {
        List<String> stops = new CopyOnWriteArrayList<>();
        List<String> program = new CopyOnWriteArrayList<>();
        CountDownLatch running = new CountDownLatch(1);
        AgentBase scout = connect(new AgentBase(options("scout", AgentKind.ROBOT)
                .withBackoff(Duration.ofMillis(20), Duration.ofMillis(200))) {
            @Override protected void onCommand(Command command, ActionHandle handle) {
                handle.started();
                running.countDown();
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
                while (!handle.isCancelRequested() && System.nanoTime() < deadline) {
                    pause();
                }
                try {
                    handle.progress(0.5, "half way");
                    handle.ended("walked");
                    program.add("reported after " + handle.cancelReason().orElse("no cancel"));
                } catch (RuntimeException e) {
                    program.add("thrown at: " + e.getMessage());
                }
            }

            @Override protected void onCancel(ActionHandle handle, String reason) {
                stops.add(reason);
                super.onCancel(handle, reason);
            }
        });
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));
        CommandTicket walk = alice.command("scout", "walk", Map.of());
        assertThat(running.await(10, TimeUnit.SECONDS)).isTrue();
        assertThat(scout.commandsInFlight()).isOne();

        server.close();

        Eventually.await("the robot's program wound down", () -> !program.isEmpty());
        assertThat(stops).containsExactly("the connection to the gateway was lost");
        assertThat(program).containsExactly("reported after the connection to the gateway was lost");
        assertThat(scout.commandsInFlight()).isZero();
        assertThatThrownBy(() -> walk.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessageContaining("the connection to the gateway was lost");
    }

    @Test
    void aCancelWithAnEmptyReason_saysNoReasonWasGiven() throws Exception {
        SlowRobot scout = connect(new SlowRobot(options("scout", AgentKind.ROBOT), false));
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));
        UserAgent bob = connect(new UserAgent(options("bob", AgentKind.USER)));
        CommandTicket walk = alice.command("scout", "walk", Map.of());
        assertThat(scout.running.await(10, TimeUnit.SECONDS)).isTrue();

        bob.cancel("scout", walk.command().id(), " ");

        assertThatThrownBy(() -> walk.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessage("cancelled: no reason given (asked by 'bob')");
    }

    @Test
    void aSecondCancelWhileTheRobotIsStopping_doesNotMakeItStopTwice() throws Exception {
        List<String> stops = new CopyOnWriteArrayList<>();
        CountDownLatch running = new CountDownLatch(1);
        CountDownLatch stopping = new CountDownLatch(1);
        connect(new AgentBase(options("scout", AgentKind.ROBOT)) {
            @Override protected void onCommand(Command command, ActionHandle handle) {
                handle.started();
                running.countDown();
            }

            @Override protected void onCancel(ActionHandle handle, String reason) {
                stops.add(reason);
                stopping.countDown();
                try {
                    Thread.sleep(500); // braking
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                handle.cancelled(reason);
            }
        });
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));
        UserAgent bob = connect(new UserAgent(options("bob", AgentKind.USER)));
        CommandTicket walk = alice.command("scout", "walk", Map.of());
        assertThat(running.await(10, TimeUnit.SECONDS)).isTrue();

        alice.cancel("scout", walk.command().id(), "stop");
        assertThat(stopping.await(10, TimeUnit.SECONDS)).isTrue();
        bob.cancel("scout", walk.command().id(), "stop now");

        assertThatThrownBy(() -> walk.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessage("cancelled: stop (asked by 'alice')");
        Thread.sleep(700); // a second onCancel, had there been one, would have run by now
        assertThat(stops).containsExactly("stop (asked by 'alice')");
    }

    @Test
    void aUserCancels_theCommandFailsAsCancelledForItsSender_andTheRobotsLateReportIsIgnored() throws Exception {
        SlowRobot scout = connect(new SlowRobot(options("scout", AgentKind.ROBOT), false));
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));
        UserAgent bob = connect(new UserAgent(options("bob", AgentKind.USER)));
        CommandTicket walk = alice.command("scout", "walk", Map.of());
        assertThat(scout.running.await(10, TimeUnit.SECONDS)).isTrue();

        // An operator other than the sender may stop it.
        bob.cancel("scout", walk.command().id(), "the room is blocked");

        assertThatThrownBy(() -> walk.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessage("cancelled: the room is blocked (asked by 'bob')");
        Eventually.await("the robot's program wound down", () -> !scout.lateReports.isEmpty());
        assertThat(scout.lateReports).containsExactly("ended after the room is blocked (asked by 'bob')");
        assertThat(walk.feedback()).extracting(f -> f.stage().name()).containsExactly("STARTED", "FAILED");
        assertThat(server.commandsInFlight()).isZero();
    }

    @Test
    void aRobotThatCanStop_answersTheCancelItself() throws Exception {
        SlowRobot scout = connect(new SlowRobot(options("scout", AgentKind.ROBOT), true));
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));
        CommandTicket walk = alice.command("scout", "walk", Map.of());
        assertThat(scout.running.await(10, TimeUnit.SECONDS)).isTrue();

        alice.cancel("scout", walk.command().id(), "changed my mind");

        assertThatThrownBy(() -> walk.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessage("stopped on the spot: changed my mind (asked by 'alice')");
    }

    @Test
    void thePlatformCancelsACommandItSent_andItsListenerHearsTheFailure() throws Exception {
        SlowRobot scout = connect(new SlowRobot(options("scout", AgentKind.ROBOT), false));
        server.actionSink().send(new Command("a-1", "scout", "walk", Map.of()));
        assertThat(scout.running.await(10, TimeUnit.SECONDS)).isTrue();

        assertThat(server.actionSink().cancel("scout", "a-1", "a newer order")).isTrue();

        Eventually.await("the engine's listener hears the failure", () -> heard.contains("failed a-1: cancelled: a newer order"));
        assertThat(server.actionSink().cancel("scout", "a-1", "again")).as("no longer in flight").isFalse();
    }

    @Test
    void aCancelOfNothingInFlight_orFromARobot_isRefused() throws Exception {
        SlowRobot scout = connect(new SlowRobot(options("scout", AgentKind.ROBOT), false));
        UserAgent alice = connect(new UserAgent(options("alice", AgentKind.USER)));

        assertThatThrownBy(() -> alice.cancel("scout", "nothing-1", "why not"))
                .isInstanceOfSatisfying(RequestRefusedException.class,
                        e -> assertThat(e.code()).isEqualTo(ErrorCode.REJECTED))
                .hasMessageContaining("No command 'nothing-1' to 'scout' is in flight.");

        CommandTicket walk = alice.command("scout", "walk", Map.of());
        assertThat(scout.running.await(10, TimeUnit.SECONDS)).isTrue();
        assertThatThrownBy(() -> scout.cancel("scout", walk.command().id(), "bored"))
                .isInstanceOfSatisfying(RequestRefusedException.class,
                        e -> assertThat(e.code()).isEqualTo(ErrorCode.FORBIDDEN))
                .hasMessageContaining("Only user and service agents may cancel commands");
        alice.cancel("scout", walk.command().id(), "done testing");
        assertThatThrownBy(() -> walk.result(WAIT)).isInstanceOf(ActionFailedException.class);
    }

    @Test
    void aCommandFromARobot_isRefused_andNothingIsSent() throws Exception {
        SlowRobot scout = connect(new SlowRobot(options("scout", AgentKind.ROBOT), false));

        assertThatThrownBy(() -> scout.command("scout", "walk", Map.of()))
                .isInstanceOfSatisfying(RequestRefusedException.class,
                        e -> assertThat(e.code()).isEqualTo(ErrorCode.FORBIDDEN))
                .hasMessageContaining("Only user and service agents may send commands;")
                .hasMessageContaining("is a robot agent, so command '");
        assertThat(scout.running.await(300, TimeUnit.MILLISECONDS)).as("no command reached a robot").isFalse();
        assertThat(server.commandsInFlight()).isZero();
    }

    /** Waits a little without holding a core: the agents' own threads are virtual and share two carriers here. */
    private static void pause() {
        try {
            Thread.sleep(5);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
