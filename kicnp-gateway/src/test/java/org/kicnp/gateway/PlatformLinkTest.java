package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.Optional;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.RequestRefusedException;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;

/** Knowledge between two K-ICNP servers on loopback: push a subtree (all or none) and pull one back. */
class PlatformLinkTest {
    private final KnowledgeBase here = KnowledgeBase.create();
    private final KnowledgeBase there = KnowledgeBase.create();
    private GatewayServer local;
    private GatewayServer remote;
    private PlatformLink link;

    @BeforeEach
    void start() {
        here.apply(java.util.List.of(
                new org.kicnp.core.Change.Add(Frame.classFrame("System").build()),
                new org.kicnp.core.Change.Add(Frame.classFrame("Robot").parent("System")
                        .slot(Slot.builder("speed", DataType.FLOAT).defaultValue(Value.of(0.5)).build()).build()),
                new org.kicnp.core.Change.Add(Frame.classFrame("Humanoid").parent("Robot").build()),
                new org.kicnp.core.Change.Add(Frame.instance("Robovie", "Humanoid").build()),
                new org.kicnp.core.Change.Add(Frame.classFrame("Drink").build())));
        AgentDirectory peers = AgentDirectory.empty().with("lab-a", "a-token", AgentKind.PEER)
                .with("lab-c", "c-token", AgentKind.PEER)
                .with("alice", "alice-token", AgentKind.USER);
        local = GatewayServer.start(GatewayConfig.defaults().withPort(0).withServerName("lab-a"), peers, here,
                FeedbackListener.NONE);
        remote = GatewayServer.start(GatewayConfig.defaults().withPort(0).withServerName("lab-b"), peers, there,
                FeedbackListener.NONE);
        link = PlatformLink.connect(AgentOptions.of("127.0.0.1", remote.port(), "lab-a", AgentKind.PEER, "a-token"),
                Duration.ofSeconds(10));
    }

    @AfterEach
    void stop() {
        link.close();
        local.close();
        remote.close();
    }

    @Test
    void push_ofWholeKnowledgeBase_isStoredThere_andPullBringsItBack() {
        assertThat(link.push(here, Optional.empty())).isEqualTo(5);
        assertThat(there.frame("Robovie").flatMap(Frame::parent)).contains("Humanoid");
        assertThat(there.value("Robovie", "speed")).contains(Value.of(0.5));

        KnowledgeBase third = KnowledgeBase.create();
        link.pullInto(third, Optional.empty());
        assertThat(third.frames()).extracting(Frame::name)
                .containsExactly("System", "Robot", "Humanoid", "Robovie", "Drink");
    }

    @Test
    void push_thatWouldReplaceTheReceiversRuntimeInstances_isForbiddenWholly_namingThem() {
        link.push(here, Optional.empty());
        // There: the presence of the connected peer, and an instance the engine (say) derived at run time.
        assertThat(there.frame("agent_lab-a").map(Frame::provenance)).contains(org.kicnp.core.Provenance.RUNTIME);
        there.put(Frame.instance("ghost", "Robot").provenance(org.kicnp.core.Provenance.RUNTIME).build());
        Frame presence = there.require("agent_lab-a");
        here.add(Frame.instance("agent_lab-a", "System").build());
        here.add(Frame.instance("ghost", "Humanoid").build());
        here.add(Frame.classFrame("Tea").parent("Drink").build());

        assertThatThrownBy(() -> link.push(here, Optional.empty()))
                .isInstanceOfSatisfying(RequestRefusedException.class,
                        e -> assertThat(e.code()).isEqualTo(ErrorCode.FORBIDDEN))
                .hasMessageContaining("'agent_lab-a'").hasMessageContaining("'ghost'")
                .hasMessageContaining("runtime");
        assertThat(there.require("agent_lab-a")).isSameAs(presence);
        assertThat(there.frame("ghost").flatMap(Frame::parent)).contains("Robot");
        assertThat(there.contains("Tea")).isFalse();
    }

    @Test
    void push_ofSubtreeWhoseParentIsMissingThere_isRefusedWholly() {
        assertThatThrownBy(() -> link.push(here, Optional.of("Robot")))
                .isInstanceOfSatisfying(RequestRefusedException.class,
                        e -> assertThat(e.code()).isEqualTo(ErrorCode.REJECTED))
                .hasMessageContaining("System");
        assertThat(there.frames()).extracting(Frame::name).doesNotContain("Robot", "Humanoid", "Robovie");
    }

    @Test
    void pull_ofSubtree_returnsRootAndEverythingBelow_withoutRuntimeFrames() {
        link.push(here, Optional.empty());
        there.put(Frame.instance("ghost", "Robot").provenance(org.kicnp.core.Provenance.RUNTIME).build());
        assertThat(link.pull(Optional.of("Robot"))).extracting(Frame::name)
                .containsExactly("Robot", "Humanoid", "Robovie");
        // A root that exists only at run time has no durable frames to send: said in words, not an empty answer.
        assertThatThrownBy(() -> link.pull(Optional.of("ghost"))).isInstanceOfSatisfying(RequestRefusedException.class,
                e -> assertThat(e.code()).isEqualTo(ErrorCode.REJECTED))
                .hasMessageContaining("'ghost' exists only at run time on this platform; pull sends durable frames");
    }

    @Test
    void push_fromNonPeer_isForbidden() {
        try (org.kicnp.agent.UserAgent alice = new org.kicnp.agent.UserAgent(
                AgentOptions.of("127.0.0.1", remote.port(), "alice", AgentKind.USER, "alice-token"))) {
            alice.startAndAwait(Duration.ofSeconds(10));
            assertThatThrownBy(() -> alice.push(here.frames())).isInstanceOfSatisfying(RequestRefusedException.class,
                    e -> assertThat(e.code()).isEqualTo(ErrorCode.FORBIDDEN));
        }
    }
    /** Frames travel one per text; an instance's list items take their type from its class in the same push. */
    @Test
    void push_ofClassAndInstanceWhoseListItemsTakeTheClassArgument_isStoredThereEqual() {
        Frame scored = Frame.classFrame("Scored").slot(Slot.builder("marks", DataType.LIST).argument("TYPE_INT").build())
                .build();
        Frame game = Frame.instance("game1", "Scored").slot(Slot.ofValue("marks", DataType.LIST,
                new Value.Lst(java.util.List.of(new Value.Int(3), new Value.Int(5))))).build();
        here.apply(java.util.List.of(new org.kicnp.core.Change.Add(scored), new org.kicnp.core.Change.Add(game)));

        link.push(here, Optional.of("Scored"));

        assertThat(there.require("game1")).isEqualTo(game);
    }

    @Test
    void pull_ofClassAndInstanceWhoseListItemsTakeTheClassArgument_bringsThemBackEqual() {
        Frame scored = Frame.classFrame("Scored").slot(Slot.builder("marks", DataType.LIST).argument("TYPE_INT").build())
                .build();
        Frame game = Frame.instance("game1", "Scored").slot(Slot.ofValue("marks", DataType.LIST,
                new Value.Lst(java.util.List.of(new Value.Int(3), new Value.Int(5))))).build();
        there.apply(java.util.List.of(new org.kicnp.core.Change.Add(scored), new org.kicnp.core.Change.Add(game)));

        assertThat(link.pull(Optional.of("Scored"))).containsExactly(scored, game);
        link.pullInto(here, Optional.of("Scored"));
        assertThat(here.require("game1")).isEqualTo(game);
    }
    /** Two different frames under one name in one push: which one is meant is unknown, so none is stored. */
    @Test
    void push_namingOneFrameTwice_isRefusedNamingItAndChangesNothing() {
        try (org.kicnp.agent.UserAgent peer = new org.kicnp.agent.UserAgent(
                AgentOptions.of("127.0.0.1", remote.port(), "lab-c", AgentKind.PEER, "c-token"))) {
            peer.startAndAwait(Duration.ofSeconds(10));
            Frame first = Frame.classFrame("Drink").slot(Slot.builder("hot", DataType.BOOLEAN).build()).build();
            Frame second = Frame.classFrame("Drink").build();

            assertThatThrownBy(() -> peer.push(java.util.List.of(Frame.classFrame("Food").build(), first, second)))
                    .isInstanceOfSatisfying(RequestRefusedException.class,
                            e -> assertThat(e.code()).isEqualTo(ErrorCode.REJECTED))
                    .hasMessageContaining("'Drink' is defined twice").hasMessageContaining("#2");
            assertThat(there.frames()).extracting(Frame::name).doesNotContain("Food", "Drink");
        }
    }
    /** A push larger than the receiver's frame limit cannot be stored; the pusher must hear why, and nothing changes. */
    @Test
    void push_largerThanTheReceiversFrameLimit_failsSayingSoAndChangesNothing() {
        addNotes(here, 3_000);
        AgentOptions generous = AgentOptions.of("127.0.0.1", remote.port(), "lab-c", AgentKind.PEER, "c-token")
                .withMaxFrameBytes(64 << 20);

        try (PlatformLink big = PlatformLink.connect(generous, Duration.ofSeconds(10))) {
            assertThatThrownBy(() -> big.push(here, Optional.of("Note")))
                    .isInstanceOfSatisfying(RequestRefusedException.class,
                            e -> assertThat(e.code()).isEqualTo(ErrorCode.FRAME_TOO_LARGE))
                    .hasMessageContaining("longer than this server accepts (1048576 bytes at most)");
        }
        assertThat(there.contains("Note")).isFalse();
    }

    /**
     * A push longer than the pusher's own frame limit is not sent at all: a large one would be cut off by the
     * receiver while it is still being written, and the pusher would only hear "connection reset".
     */
    @Test
    void push_largerThanThePushersFrameLimit_isNotSentAndTheLinkStaysUp() {
        addNotes(here, 300);
        AgentOptions small = AgentOptions.of("127.0.0.1", remote.port(), "lab-c", AgentKind.PEER, "c-token")
                .withMaxFrameBytes(64 << 10);

        try (PlatformLink tight = PlatformLink.connect(small, Duration.ofSeconds(10))) {
            assertThatThrownBy(() -> tight.push(here, Optional.of("Note")))
                    .isInstanceOfSatisfying(RequestRefusedException.class,
                            e -> assertThat(e.code()).isEqualTo(ErrorCode.FRAME_TOO_LARGE))
                    .hasMessageContaining("The push message is")
                    .hasMessageContaining("more than one message may carry (65536 bytes")
                    .hasMessageContaining("nothing was sent");
            assertThat(there.contains("Note")).isFalse();
            assertThat(tight.pull(Optional.empty())).as("still connected").extracting(Frame::name).doesNotContain("Note");
        }
    }
    /** An answer longer than one message may carry is refused as such; the link stays up for smaller pulls. */
    @Test
    void pull_ofMoreThanOneMessageCarries_isRefusedSayingSoAndTheLinkStaysUp() {
        addNotes(there, 3_000);
        there.add(Frame.classFrame("Small").build());

        assertThatThrownBy(() -> link.pull(Optional.of("Note")))
                .isInstanceOfSatisfying(RequestRefusedException.class,
                        e -> assertThat(e.code()).isEqualTo(ErrorCode.REJECTED))
                .hasMessageContaining("more than one message may carry (1048576 bytes)");
        assertThat(link.pull(Optional.of("Small"))).extracting(Frame::name).containsExactly("Small");
    }
    /** "Parents first" (docs/protocol.md): also for a frame moved below a class added after it. */
    @Test
    void pull_ofAFrameMovedBelowALaterClass_givesTheParentFirst() {
        there.add(Frame.classFrame("Machine").build());
        there.add(Frame.classFrame("Vehicle").build());
        there.replace(Frame.classFrame("Machine").parent("Vehicle").build());
        there.add(Frame.instance("car1", "Machine").build());

        assertThat(link.pull(Optional.of("Vehicle"))).extracting(Frame::name)
                .containsExactly("Vehicle", "Machine", "car1");
    }

    /** Adds class Note and {@code count} instances of it, 400 characters of text each, to {@code kb} in one batch. */
    private static void addNotes(KnowledgeBase kb, int count) {
        java.util.List<org.kicnp.core.Change> many = new java.util.ArrayList<>();
        many.add(new org.kicnp.core.Change.Add(Frame.classFrame("Note").slot(Slot.builder("text", DataType.STRING)
                .build()).build()));
        for (int i = 0; i < count; i++) {
            many.add(new org.kicnp.core.Change.Add(Frame.instance("note" + i, "Note")
                    .slot(Slot.ofValue("text", DataType.STRING, Value.of("x".repeat(400)))).build()));
        }
        kb.apply(many);
    }
}
