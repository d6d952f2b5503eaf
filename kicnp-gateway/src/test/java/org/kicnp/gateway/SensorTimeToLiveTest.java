package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;

/**
 * A sensor signal with a time to live, over real sockets: it is retracted when its time is over unless a newer signal
 * of the same sensor replaced it, so a slot condition never rests on a reading the robot stopped giving.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class SensorTimeToLiveTest {
    private static final Duration WAIT = Duration.ofSeconds(10);
    private static final String FRAME = "signal_scout_obstacle";
    private final KnowledgeBase kb = KnowledgeBase.create();
    private GatewayServer server;
    private UserAgent scout;

    @BeforeEach
    void start() {
        server = GatewayServer.start(GatewayConfig.defaults().withPort(0),
                AgentDirectory.empty().with("scout", "scout-token", AgentKind.ROBOT)
                        .with("alice", "alice-token", AgentKind.USER), kb, FeedbackListener.NONE);
        scout = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "scout", AgentKind.ROBOT, "scout-token"));
        scout.startAndAwait(WAIT);
    }

    @AfterEach
    void stop() {
        scout.close();
        server.close();
    }

    /** Whether the sensor's frame is there and holds {@code value} now. */
    private boolean holds(Value value) {
        return kb.frame(FRAME).flatMap(f -> f.ownSlot("value")).flatMap(s -> s.effectiveValue())
                .equals(java.util.Optional.of(value));
    }

    @Test
    void aSignalWithATimeToLive_isRetractedWhenItIsOver_andNotBefore() {
        long sent = System.nanoTime();
        scout.sensor("obstacle", Duration.ofMillis(300), Value.of(0.4));
        Eventually.await("the reading is in the knowledge base", () -> kb.contains(FRAME));
        long time = ((Value.Int) kb.value(FRAME, "time").orElseThrow()).value();
        assertThat(kb.value(FRAME, "expires")).contains(Value.of(time + 300));
        assertThat(kb.value(FRAME, "value")).contains(Value.of(0.4));

        Eventually.await("the reading expired", () -> !kb.contains(FRAME));
        assertThat(Duration.ofNanos(System.nanoTime() - sent)).isGreaterThanOrEqualTo(Duration.ofMillis(300));
        assertThat(scout.isConnected()).isTrue();
    }

    @Test
    void aNewerSignal_replacesTheReading_andTheOlderOnesClockTakesNothing() throws InterruptedException {
        scout.sensor("obstacle", Duration.ofMillis(200), Value.of(0.4));
        scout.sensor("obstacle", Duration.ofMinutes(10), Value.of(0.9));
        Eventually.await("the newer reading is in", () -> holds(Value.of(0.9)));

        Thread.sleep(800); // well past the first reading's 200 ms
        assertThat(kb.value(FRAME, "value")).contains(Value.of(0.9));
    }

    @Test
    void aSignalWithoutATimeToLive_afterOneWithIt_holdsUntilReplaced() throws InterruptedException {
        scout.sensor("obstacle", Duration.ofMillis(200), Value.of(0.4));
        scout.sensor("obstacle", Value.of(false));
        Eventually.await("the reading without a time to live is in", () -> holds(Value.of(false)));

        Thread.sleep(800);
        assertThat(kb.contains(FRAME)).isTrue();
        assertThat(kb.value(FRAME, "expires")).isEmpty();
    }

    @Test
    void aSignalHoldingAList_reachesSubscribersAndQueries_asTheXmlOfItsFrame_andSubscribersWithItsValuesTyped() {
        try (UserAgent alice = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "alice", AgentKind.USER,
                "alice-token"))) {
            alice.startAndAwait(WAIT);
            kb.add(org.kicnp.core.Frame.classFrame("SensorSignal").build());
            alice.subscribe("SensorSignal");
            // Robovie's face_seen: a name, the face descriptor (a list), distance and bearing.
            Value face = new Value.Lst(java.util.List.of(Value.of(0.1), Value.of(0.2)));
            scout.sensor("face_seen", Duration.ofSeconds(30), Value.of("unknown"), face, Value.of(1.2));

            Eventually.await("alice hears of the signal", () -> !alice.changes().isEmpty());
            assertThat(alice.changes().getFirst().name()).isEqualTo("signal_scout_face_seen");
            assertThat(alice.changes().getFirst().frame()).hasValueSatisfying(xml -> assertThat(xml)
                    .contains("<ITEM>unknown</ITEM>").contains("<ITEM>0.1</ITEM>"));
            // The XML's list has no item type, so its items read back as text; the notification carries them typed.
            assertThat(alice.changes().getFirst().values()).contains(java.util.List.of(Value.of("unknown"), face,
                    Value.of(1.2)));
            assertThat(alice.query("SensorSignal")).singleElement().satisfies(f -> assertThat(f.ownSlot("values")
                    .flatMap(org.kicnp.core.Slot::value)).contains(new Value.Lst(java.util.List.of(Value.of("unknown"),
                    new Value.Lst(java.util.List.of(Value.of("0.1"), Value.of("0.2"))), Value.of("1.2")))));
        }
    }

    @Test
    void aTimeToLiveOutOfRange_isRefusedByTheSdk_beforeAnythingIsSent() {
        for (Duration bad : new Duration[] {Duration.ZERO, Duration.ofMillis(-1), Duration.ofNanos(1_500_000),
                Duration.ofDays(1).plusMillis(1)}) {
            assertThatThrownBy(() -> scout.sensor("obstacle", bad, Value.of(1L)))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("The time to live of sensor 'obstacle' must be a whole number of "
                            + "milliseconds from 1 ms to a day");
        }
        assertThat(kb.contains(FRAME)).isFalse();
        assertThat(scout.isConnected()).isTrue();
    }
}
