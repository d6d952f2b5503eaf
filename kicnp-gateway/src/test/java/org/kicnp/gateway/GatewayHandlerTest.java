package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.netty.buffer.Unpooled;
import io.netty.channel.embedded.EmbeddedChannel;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.FeedbackStage;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.Command;

/** The gateway pipeline and handler on an {@link EmbeddedChannel}: codec, authentication, dispatch, cleanup. */
class GatewayHandlerTest {
    private final KnowledgeBase kb = KnowledgeBase.create();
    private final GatewayMetrics metrics = new GatewayMetrics();
    private final List<String> heard = new CopyOnWriteArrayList<>();
    private final ServerAgent[] server = new ServerAgent[1];
    private final EmbeddedChannel ch = Wire.channel(GatewayConfig.defaults().withMaxFrameBytes(4096),
            AgentDirectory.empty().with("scout", "s3cret", AgentKind.ROBOT), kb, new Recorder(), metrics, server);

    @AfterEach
    void close() {
        ch.finishAndReleaseAll();
    }

    @Test
    void hello_withRightToken_isAccepted() {
        ch.writeInbound(Wire.frame(new Message.Hello("1", "scout", AgentKind.ROBOT, "s3cret")));
        assertThat(Wire.written(ch)).containsExactly(new Message.AuthResult("1", true, "kicnp", Optional.empty()));
        assertThat(ch.isOpen()).isTrue();
    }

    @Test
    void hello_withWrongToken_isRefusedAndClosed() {
        ch.writeInbound(Wire.frame(new Message.Hello("1", "scout", AgentKind.ROBOT, "guess")));
        assertThat(Wire.written(ch)).containsExactly(new Message.AuthResult("1", false, "kicnp",
                Optional.of("Unknown agent 'scout' or wrong token.")));
        assertThat(ch.isOpen()).isFalse();
    }

    @Test
    void hello_withKindNotAllowed_isRefusedAndClosed() {
        ch.writeInbound(Wire.frame(new Message.Hello("1", "scout", AgentKind.USER, "s3cret")));
        assertThat(Wire.written(ch)).singleElement().isEqualTo(new Message.AuthResult("1", false, "kicnp",
                Optional.of("Agent 'scout' may not connect as a user agent.")));
        assertThat(ch.isOpen()).isFalse();
    }

    @Test
    void anyMessage_beforeHello_getsNotAuthenticatedAndClose() {
        ch.writeInbound(Wire.frame(new Message.Query("1", "Robot")));
        assertError(ErrorCode.NOT_AUTHENTICATED, "Send 'hello' first: 'query' before authentication.");
        assertThat(ch.isOpen()).isFalse();
        assertThat(metrics.protocolErrors()).isEqualTo(1);
    }

    /** The refusal answers that request: it echoes its id, as docs/protocol.md's Correlation says answers do. */
    @Test
    void request_beforeHello_getsNotAuthenticatedEchoingItsId() {
        ch.writeInbound(Wire.frame(new Message.Ask("a-7", "Robot", "speed")));
        assertThat(Wire.written(ch)).containsExactly(Message.ErrorReply.to("a-7", ErrorCode.NOT_AUTHENTICATED,
                "Send 'hello' first: 'ask' before authentication."));
        assertThat(ch.isOpen()).isFalse();
    }

    @Test
    void garbageBytes_getFrameTooLargeAndClose() {
        ch.writeInbound(Unpooled.copiedBuffer("GET / HTTP/1.1\r\nHost: x\r\n\r\n", StandardCharsets.US_ASCII));
        assertError(ErrorCode.FRAME_TOO_LARGE, "longer than this server accepts");
        assertThat(ch.isOpen()).isFalse();
    }

    @Test
    void oversizeFrame_isRefusedBeforeItsBytesArrive() {
        io.netty.buffer.ByteBuf header = Unpooled.buffer(4).writeInt(4097);
        ch.writeInbound(header);
        // The sizes of the payload, as the agent wrote it and as docs/protocol.md counts the limit (not with the
        // 4-byte prefix that Netty's own message adds).
        assertError(ErrorCode.FRAME_TOO_LARGE, "A frame of 4097 bytes is longer than this server accepts "
                + "(4096 bytes at most).");
        assertThat(ch.isOpen()).isFalse();
    }

    @Test
    void badJson_getsBadJsonAndClose() {
        ch.writeInbound(Wire.frame("{\"v\":1,\"type\":"));
        assertError(ErrorCode.BAD_JSON, "not valid JSON");
        assertThat(ch.isOpen()).isFalse();
    }

    @Test
    void unknownType_getsUnknownTypeAndClose() {
        ch.writeInbound(Wire.frame("{\"v\":1,\"type\":\"teleport\",\"id\":\"1\"}"));
        assertError(ErrorCode.UNKNOWN_TYPE, "Unknown message type 'teleport'.");
        assertThat(ch.isOpen()).isFalse();
    }

    @Test
    void register_createsPresence_andClose_retractsIt() {
        authenticate();
        ch.writeInbound(Wire.frame(new Message.Register("2", List.of())));
        assertThat(Wire.written(ch)).containsExactly(new Message.Ack("2"));
        assertThat(kb.frame("agent_scout")).hasValueSatisfying(f -> assertThat(f.parent()).contains("Presence"));
        assertThat(kb.value("agent_scout", "kind")).contains(Value.of("robot"));

        ch.close();
        assertThat(kb.contains("agent_scout")).isFalse();
    }

    /** Capability frames travel one per text; a frame below a capability class inherits its list's item type. */
    @Test
    void register_ofAClassAndASubclassWhoseListDefaultTakesTheClassArgument_storesBothAsSent() {
        authenticate();
        Frame skill = Frame.classFrame("Skill").slot(org.kicnp.core.Slot.builder("levels", org.kicnp.core.DataType.LIST)
                .argument("TYPE_INT").build()).build();
        Frame fast = Frame.classFrame("FastSkill").parent("Skill").slot(org.kicnp.core.Slot.builder("levels",
                org.kicnp.core.DataType.LIST).defaultValue(new org.kicnp.core.Value.Lst(List.of(
                        new org.kicnp.core.Value.Int(1), new org.kicnp.core.Value.Int(2)))).build()).build();

        ch.writeInbound(Wire.frame(new Message.Register("2", org.kicnp.protocol.FrameText.toXml(List.of(skill, fast)))));

        assertThat(Wire.written(ch)).containsExactly(new Message.Ack("2"));
        assertThat(kb.require("FastSkill")).isEqualTo(fast);
    }

    /** Two capability frames of one name: which is meant is unknown, so neither is stored. */
    @Test
    void register_namingOneFrameTwice_isRejectedAndChangesNothing() {
        authenticate();
        List<String> capabilities = org.kicnp.protocol.FrameText.toXml(List.of(Frame.classFrame("Fetch").build(),
                Frame.classFrame("Fetch").slot(org.kicnp.core.Slot.builder("item", org.kicnp.core.DataType.STRING)
                        .build()).build()));

        ch.writeInbound(Wire.frame(new Message.Register("2", capabilities)));

        assertThat(Wire.written(ch)).singleElement().isInstanceOfSatisfying(Message.ErrorReply.class, e -> {
            assertThat(e.code()).isEqualTo(ErrorCode.REJECTED);
            assertThat(e.message()).contains("'Fetch' is defined twice");
        });
        assertThat(kb.contains("Fetch")).isFalse();
    }

    @Test
    void register_overAnInstanceABehaviorFrameOrAClassElsewhere_isForbiddenAndChangesNothing() {
        kb.add(Frame.classFrame("User").build());
        kb.add(Frame.classFrame("Action").build());
        kb.add(Frame.classFrame("Greeting").slot(org.kicnp.core.Slot.builder("mUser", org.kicnp.core.DataType.INSTANCE)
                .argument("User").required(true).build()).build());
        kb.add(Frame.instance("taro", "User").build());
        authenticate();
        List<String> capabilities = org.kicnp.protocol.FrameText.toXml(List.of(
                Frame.classFrame("Greeting").build(), Frame.classFrame("taro").build(),
                Frame.classFrame("User").parent("Action").build(), Frame.classFrame("Fetch").parent("Action").build()));

        ch.writeInbound(Wire.frame(new Message.Register("2", capabilities)));

        assertThat(Wire.written(ch)).singleElement().isInstanceOfSatisfying(Message.ErrorReply.class, e -> {
            assertThat(e.code()).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(e.message()).startsWith("The capabilities of ").contains(
                    "Frame 'Greeting' is a behavior frame of the knowledge base; a capability may not replace it.",
                    "Frame 'taro' is an instance of the knowledge base; a capability may not replace it.",
                    "Frame 'User' is a root class; a capability of that name below 'Action' would move it.")
                    .doesNotContain("'Fetch'");
        });
        assertThat(kb.require("Greeting").slots()).hasSize(1);
        assertThat(kb.require("taro").isInstance()).isTrue();
        assertThat(kb.require("User").parent()).isEmpty();
        assertThat(kb.contains("Fetch")).as("all or none").isFalse();
        assertThat(kb.contains("agent_scout")).isFalse();
        assertThat(ch.isOpen()).isTrue();
    }

    @Test
    void register_overABehaviorFrameThatInheritsItsRequiredInstanceSlot_isForbidden() {
        kb.add(Frame.classFrame("User").build());
        kb.add(Frame.classFrame("Reply").slot(org.kicnp.core.Slot.builder("mUser", org.kicnp.core.DataType.INSTANCE)
                .argument("User").required(true).build()).build());
        kb.add(Frame.classFrame("LoudReply").parent("Reply").build());
        authenticate();

        ch.writeInbound(Wire.frame(new Message.Register("2", List.of(org.kicnp.protocol.FrameText.toXml(
                Frame.classFrame("LoudReply").parent("Reply").build())))));

        assertError(ErrorCode.FORBIDDEN,
                "Frame 'LoudReply' is a behavior frame of the knowledge base; a capability may not replace it.");
    }

    @Test
    void register_again_replacesItsCapabilityFrame() {
        kb.add(Frame.classFrame("Action").build());
        authenticate();
        ch.writeInbound(Wire.frame(new Message.Register("2", List.of(org.kicnp.protocol.FrameText.toXml(
                Frame.classFrame("Fetch").parent("Action").build())))));
        ch.writeInbound(Wire.frame(new Message.Register("3", List.of(org.kicnp.protocol.FrameText.toXml(
                Frame.classFrame("Fetch").parent("Action").slot(org.kicnp.core.Slot.builder("item",
                        org.kicnp.core.DataType.STRING).build()).build())))));

        assertThat(Wire.written(ch)).containsExactly(new Message.Ack("2"), new Message.Ack("3"));
        assertThat(kb.require("Fetch").ownSlot("item")).isPresent();
    }

    @Test
    void register_usesRobotAgentClass_whenTheKnowledgeBaseHasOne() {
        kb.add(Frame.classFrame("Agent").build());
        kb.add(Frame.classFrame("RobotAgent").parent("Agent").build());
        register();
        assertThat(kb.frame("agent_scout").flatMap(Frame::parent)).contains("RobotAgent");
        assertThat(kb.contains("Presence")).isFalse();
    }

    @Test
    void commands_inFlightPerRobot_areBounded() {
        register();
        for (int i = 0; i < Commands.MAX_IN_FLIGHT_PER_ROBOT; i++) {
            server[0].commands().send(new Command("c" + i, "scout", "walk", Map.of()));
        }
        Wire.written(ch);
        assertThatThrownBy(() -> server[0].commands().send(new Command("one-more", "scout", "walk", Map.of())))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("Agent 'scout' already has 1024 commands in flight; command 'one-more' was not sent.");
        ch.writeInbound(Wire.frame(new Message.Feedback("c0", "scout", FeedbackStage.FAILED, Optional.empty(), "no")));
        server[0].commands().send(new Command("one-more", "scout", "walk", Map.of()));
        assertThat(server[0].commands().inFlightCount()).isEqualTo(Commands.MAX_IN_FLIGHT_PER_ROBOT);
    }

    @Test
    void sensorSignal_becomesRuntimeFrameStampedWithTheSender() {
        authenticate();
        ch.writeInbound(Wire.frame(new Message.SensorSignal("someone-else", "sonar", List.of(Value.of(0.75)))));
        assertThat(kb.value("signal_scout_sonar", "value")).contains(Value.of(0.75));
        assertThat(kb.value("signal_scout_sonar", "source")).contains(Value.of("scout"));
        assertThat(kb.require("signal_scout_sonar").provenance()).isEqualTo(org.kicnp.core.Provenance.RUNTIME);
    }

    /**
     * Robot 'arm' sensor 'left_grip' and robot 'arm_left' sensor 'grip' both map to 'signal_arm_left_grip': one
     * agent's reading may not replace another's (and be retracted when the wrong agent leaves).
     */
    @Test
    void sensorSignal_whoseFrameNameIsAnotherAgentsSignal_isRejectedAndKeepsThatSignal() {
        ServerAgent[] two = new ServerAgent[1];
        KnowledgeBase shared = KnowledgeBase.create();
        EmbeddedChannel armLeft = Wire.channel(GatewayConfig.defaults(), AgentDirectory.empty().with("arm", "s")
                .with("arm_left", "t"), shared, FeedbackListener.NONE, new GatewayMetrics(), two);
        EmbeddedChannel arm = Wire.channel(GatewayConfig.defaults(), two[0], new GatewayMetrics());
        try {
            armLeft.writeInbound(Wire.frame(new Message.Hello("1", "arm_left", AgentKind.ROBOT, "t")));
            arm.writeInbound(Wire.frame(new Message.Hello("1", "arm", AgentKind.ROBOT, "s")));
            Wire.written(armLeft);
            Wire.written(arm);
            armLeft.writeInbound(Wire.frame(new Message.SensorSignal("arm_left", "grip", List.of(Value.of(true)))));

            arm.writeInbound(Wire.frame(new Message.SensorSignal("arm", "left_grip", List.of(Value.of(false)))));

            assertThat(Wire.written(arm)).singleElement().isInstanceOfSatisfying(Message.ErrorReply.class, e -> {
                assertThat(e.code()).isEqualTo(ErrorCode.REJECTED);
                assertThat(e.message()).isEqualTo("Sensor signal 'left_grip' from 'arm' was refused: its frame "
                        + "'signal_arm_left_grip' holds sensor 'grip' of agent 'arm_left'; rename the sensor.");
            });
            assertThat(shared.value("signal_arm_left_grip", "value")).contains(Value.of(true));
            arm.close();
            assertThat(shared.value("signal_arm_left_grip", "source")).contains(Value.of("arm_left"));
        } finally {
            armLeft.finishAndReleaseAll();
            arm.finishAndReleaseAll();
        }
    }

    @Test
    void sensorSignalsWithATimeToLive_keepOneExpiryPerSensor_howeverManyReadingsCome() {
        authenticate();
        for (int i = 0; i < 1_000; i++) {
            ch.writeInbound(Wire.frame(new Message.SensorSignal("scout", "sonar", List.of(Value.of((long) i)),
                    Optional.of(Message.SensorSignal.MAX_TTL_MS))));
        }
        ch.writeInbound(Wire.frame(new Message.SensorSignal("scout", "bumper", List.of(Value.of(true)),
                Optional.of(60_000L))));
        assertThat(kb.value("signal_scout_sonar", "value")).contains(Value.of(999L));
        assertThat(server[0].runtime().pendingExpiries()).isEqualTo(2);

        ch.writeInbound(Wire.frame(new Message.SensorSignal("scout", "sonar", List.of(Value.of(0L)))));
        assertThat(server[0].runtime().pendingExpiries()).isEqualTo(1);
        ch.close();
        assertThat(server[0].runtime().pendingExpiries()).isZero();
    }

    @Test
    void command_reachesRobot_andFeedbackReachesListenerAndKnowledgeBase() {
        register();
        Command fetch = new Command("c1", "scout", "fetch", Map.of("item", "tea"));
        server[0].commands().send(fetch);
        assertThat(Wire.written(ch)).containsExactly(fetch);

        ch.writeInbound(Wire.frame(new Message.Feedback("c1", "scout", FeedbackStage.STARTED, Optional.empty(), "")));
        ch.writeInbound(Wire.frame(new Message.Feedback("c1", "scout", FeedbackStage.ENDED, Optional.empty(), "tea served")));
        assertThat(heard).containsExactly("started c1", "ended c1: tea served");
        assertThat(kb.value("feedback_scout_fetch", "status")).contains(Value.of("ended"));
        assertThat(server[0].commands().inFlightCount()).isZero();
    }

    @Test
    void disconnect_duringCommand_failsItWithReason() {
        register();
        server[0].commands().send(new Command("c2", "scout", "walk", Map.of()));
        ch.close();
        assertThat(heard).containsExactly("failed c2: agent 'scout' disconnected");
        assertThat(kb.value("feedback_scout_walk", "status")).contains(Value.of("failed"));
    }

    @Test
    void command_toAbsentRobot_failsThroughListener() {
        server[0].commands().send(new Command("c3", "pino", "walk", Map.of()));
        assertThat(heard).containsExactly("failed c3: Agent 'pino' is not connected, so command 'c3' cannot be sent.");
    }

    @Test
    void assertAndQuery_roundTripFramesAsXml() {
        kb.add(Frame.classFrame("Cup").build());
        authenticate();
        String cup = org.kicnp.protocol.FrameText.toXml(Frame.instance("cup1", "Cup").build());
        ch.writeInbound(Wire.frame(new Message.Assert("2", cup)));
        ch.writeInbound(Wire.frame(new Message.Query("3", "Cup")));
        List<Message> out = Wire.written(ch);
        assertThat(out.get(0)).isEqualTo(new Message.Ack("2"));
        assertThat(((Message.Frames) out.get(1)).frames()).singleElement().asString().contains("<NAME>cup1</NAME>");
    }

    @Test
    void assert_overAClassOrDeclaredInstance_isForbiddenAndKeepsThem() {
        kb.add(Frame.classFrame("Cup").build());
        kb.add(Frame.classFrame("Tea").parent("Cup").build());
        kb.add(Frame.instance("cup1", "Cup").build());
        authenticate();

        ch.writeInbound(Wire.frame(new Message.Assert("2",
                org.kicnp.protocol.FrameText.toXml(Frame.instance("Tea", "Cup").build()))));
        assertError(ErrorCode.FORBIDDEN, "Frame 'Tea' is a class; an assert may add or replace runtime instances only.");
        ch.writeInbound(Wire.frame(new Message.Assert("3",
                org.kicnp.protocol.FrameText.toXml(Frame.instance("cup1", "Cup").build()))));
        assertError(ErrorCode.FORBIDDEN,
                "Frame 'cup1' is declared knowledge; an assert may add or replace runtime instances only.");

        assertThat(kb.require("Tea").isInstance()).isFalse();
        assertThat(kb.require("cup1").provenance()).isEqualTo(org.kicnp.core.Provenance.DECLARED);
        assertThat(ch.isOpen()).isTrue();
    }

    @Test
    void assert_ofSeveralInstances_storesThemAllOrNone() {
        kb.add(Frame.classFrame("Cup").build());
        kb.add(Frame.instance("cup0", "Cup").build());
        authenticate();
        String two = org.kicnp.protocol.FrameText.document(List.of(Frame.instance("cup1", "Cup").build(),
                Frame.instance("cup2", "Cup").build()));
        String oneForbidden = two.replace("<NAME>cup2</NAME>", "<NAME>cup0</NAME>").replace("cup1", "cup3");

        ch.writeInbound(Wire.frame(new Message.Assert("2", two)));
        assertThat(Wire.written(ch)).containsExactly(new Message.Ack("2"));
        assertThat(kb.contains("cup1")).isTrue();
        assertThat(kb.require("cup2").provenance()).isEqualTo(org.kicnp.core.Provenance.RUNTIME);

        ch.writeInbound(Wire.frame(new Message.Assert("3", oneForbidden)));
        assertError(ErrorCode.FORBIDDEN, "Frame 'cup0' is declared knowledge");
        assertThat(kb.contains("cup3")).as("nothing of a refused assert is stored").isFalse();
    }

    @Test
    void assert_again_replacesTheRuntimeInstance() {
        kb.add(Frame.classFrame("Cup").build());
        authenticate();
        ch.writeInbound(Wire.frame(new Message.Assert("2",
                org.kicnp.protocol.FrameText.toXml(Frame.instance("cup1", "Cup").build()))));
        ch.writeInbound(Wire.frame(new Message.Assert("3", org.kicnp.protocol.FrameText.toXml(
                Frame.instance("cup1", "Cup").slot(org.kicnp.core.Slot.builder("full", org.kicnp.core.DataType.BOOLEAN)
                        .value(Value.of(true)).build()).build()))));

        assertThat(Wire.written(ch)).containsExactly(new Message.Ack("2"), new Message.Ack("3"));
        assertThat(kb.value("cup1", "full")).contains(Value.of(true));
    }

    @Test
    void destroy_ofClass_isForbiddenButConnectionStaysOpen() {
        kb.add(Frame.classFrame("Cup").build());
        authenticate();
        ch.writeInbound(Wire.frame(new Message.Destroy("2", "Cup")));
        assertError(ErrorCode.FORBIDDEN, "Frame 'Cup' is a class; agents may destroy instances only.");
        assertThat(ch.isOpen()).isTrue();
    }

    @Test
    void destroy_ofDeclaredOrLearnedInstance_isForbiddenAndKeepsIt() {
        kb.add(Frame.classFrame("Cup").build());
        kb.add(Frame.instance("cup1", "Cup").build());
        kb.add(Frame.instance("cup2", "Cup").provenance(org.kicnp.core.Provenance.LEARNED).build());
        authenticate();

        ch.writeInbound(Wire.frame(new Message.Destroy("2", "cup1")));
        assertError(ErrorCode.FORBIDDEN,
                "Frame 'cup1' is declared knowledge; agents may destroy runtime instances only.");
        ch.writeInbound(Wire.frame(new Message.Destroy("3", "cup2")));
        assertError(ErrorCode.FORBIDDEN,
                "Frame 'cup2' is learned knowledge; agents may destroy runtime instances only.");

        assertThat(kb.require("cup1").provenance()).isEqualTo(org.kicnp.core.Provenance.DECLARED);
        assertThat(kb.require("cup2").provenance()).isEqualTo(org.kicnp.core.Provenance.LEARNED);
        assertThat(ch.isOpen()).isTrue();
    }

    @Test
    void destroy_ofRuntimeInstance_removesIt() {
        kb.add(Frame.classFrame("Cup").build());
        kb.add(Frame.instance("cup1", "Cup").provenance(org.kicnp.core.Provenance.RUNTIME).build());
        authenticate();

        ch.writeInbound(Wire.frame(new Message.Destroy("2", "cup1")));

        assertThat(Wire.written(ch)).containsExactly(new Message.Ack("2"));
        assertThat(kb.contains("cup1")).isFalse();
    }

    @Test
    void serverOnlyMessage_fromAgent_isBadMessage() {
        authenticate();
        ch.writeInbound(Wire.frame(new Message.Ack("9")));
        assertError(ErrorCode.BAD_MESSAGE, "'ack' is sent by the server, never to it.");
        assertThat(ch.isOpen()).isFalse();
    }

    private void authenticate() {
        ch.writeInbound(Wire.frame(new Message.Hello("1", "scout", AgentKind.ROBOT, "s3cret")));
        assertThat(Wire.written(ch)).hasSize(1);
    }

    private void register() {
        authenticate();
        ch.writeInbound(Wire.frame(new Message.Register("2", List.of())));
        assertThat(Wire.written(ch)).containsExactly(new Message.Ack("2"));
    }

    private void assertError(ErrorCode code, String messagePart) {
        assertThat(Wire.written(ch)).singleElement().isInstanceOfSatisfying(Message.ErrorReply.class, e -> {
            assertThat(e.code()).isEqualTo(code);
            assertThat(e.message()).contains(messagePart);
        });
    }

    private final class Recorder implements FeedbackListener {
        @Override public void started(Command c) {
            heard.add("started " + c.id());
        }

        @Override public void ended(Command c, String result) {
            heard.add("ended " + c.id() + ": " + result);
        }

        @Override public void failed(Command c, String reason) {
            heard.add("failed " + c.id() + ": " + reason);
        }
    }
}
