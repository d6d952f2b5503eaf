package org.kicnp.gateway;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.kicnp.agent.ActionFailedException;
import org.kicnp.agent.ActionHandle;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.AuthenticationException;
import org.kicnp.agent.CommandTicket;
import org.kicnp.agent.RequestRefusedException;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.ChangeKind;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.FeedbackStage;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.Command;

/** Real sockets on 127.0.0.1 (ephemeral ports), several agents built on the SDK, and raw clients. */
class GatewayEndToEndTest {
    static final Duration WAIT = Duration.ofSeconds(10);
    static final AgentDirectory AGENTS = AgentDirectory.empty()
            .with("scout", "scout-token", AgentKind.ROBOT)
            .with("pino", "pino-token", AgentKind.ROBOT)
            .with("alice", "alice-token", AgentKind.USER)
            .with("bob", "bob-token", AgentKind.USER);

    private final KnowledgeBase kb = KnowledgeBase.create();
    private final List<String> heard = new CopyOnWriteArrayList<>();
    private final List<AutoCloseable> open = new ArrayList<>();
    private GatewayServer server;

    @BeforeEach
    void start() {
        kb.add(Frame.classFrame("Cup").build());
        server = GatewayServer.start(GatewayConfig.defaults().withPort(0), AGENTS, kb, new Recorder(heard));
    }

    @AfterEach
    void stop() throws Exception {
        for (AutoCloseable c : open.reversed()) {
            c.close();
        }
        server.close();
    }

    @Test
    void relay_toName_reachesOnlyThatAgent() {
        UserAgent alice = user("alice");
        UserAgent bob = user("bob");
        UserAgent scout = connect(new UserAgent(options("scout", AgentKind.ROBOT)));
        alice.relayTo("bob", "greeting", "Hi, bob.");
        Eventually.await("bob hears alice", () -> !bob.relays().isEmpty());
        assertThat(bob.relays()).singleElement().satisfies(r -> {
            assertThat(r.from()).isEqualTo("alice");
            assertThat(r.body()).isEqualTo("Hi, bob.");
        });
        assertThat(scout.relays()).isEmpty();
    }

    @Test
    void relay_toKind_reachesEveryAgentOfThatKind() {
        UserAgent alice = user("alice");
        UserAgent bob = user("bob");
        UserAgent scout = connect(new UserAgent(options("scout", AgentKind.ROBOT)));
        UserAgent pino = connect(new UserAgent(options("pino", AgentKind.ROBOT)));
        alice.relayToKind(AgentKind.ROBOT, "stop", "Everyone stop.");
        Eventually.await("both robots hear it", () -> scout.relays().size() == 1 && pino.relays().size() == 1);
        assertThat(bob.relays()).isEmpty();
        assertThat(alice.relays()).isEmpty();
    }

    @Test
    void relay_toKindWithNoAgentOfIt_isRefusedWithCode() {
        UserAgent alice = user("alice");
        assertThatThrownBy(() -> alice.relayToKind(AgentKind.ROBOT, "stop", "Everyone stop."))
                .isInstanceOfSatisfying(RequestRefusedException.class,
                        e -> assertThat(e.code()).isEqualTo(ErrorCode.UNKNOWN_AGENT))
                .hasMessage("No other agent of kind 'robot' is registered, so nobody received the relay.");
    }

    @Test
    void tell_toName_reachesThatAgent_andToUnknownAgentDoesNotThrow() {
        UserAgent alice = user("alice");
        UserAgent bob = user("bob");
        alice.tellTo("aibo", "s", "nobody hears this");
        alice.tellTo("bob", "greeting", "Hi, bob.");
        Eventually.await("bob hears alice", () -> !bob.relays().isEmpty());
        assertThat(bob.relays()).singleElement().satisfies(r -> {
            assertThat(r.from()).isEqualTo("alice");
            assertThat(r.body()).isEqualTo("Hi, bob.");
        });
    }

    @Test
    void relay_toUnknownAgent_isRefusedWithCode() {
        UserAgent alice = user("alice");
        assertThatThrownBy(() -> alice.relayTo("aibo", "s", "b"))
                .isInstanceOfSatisfying(RequestRefusedException.class,
                        e -> assertThat(e.code()).isEqualTo(ErrorCode.UNKNOWN_AGENT))
                .hasMessage("No agent 'aibo' is registered.");
    }

    @Test
    void command_fromUser_andFromPlatform_roundTripWithFeedback() {
        connect(new org.kicnp.example.TeaRobot(options("scout", AgentKind.ROBOT)));
        UserAgent alice = user("alice");
        CommandTicket ticket = alice.command("scout", "bring", Map.of("item", "tea"));
        assertThat(ticket.result(WAIT)).isEqualTo("brought a cup of tea");
        assertThat(ticket.feedback()).extracting(Message.Feedback::stage).containsExactly(FeedbackStage.STARTED,
                FeedbackStage.PROGRESS, FeedbackStage.PROGRESS, FeedbackStage.PROGRESS, FeedbackStage.ENDED);

        server.actionSink().send(new Command("plan-1", "scout", "bring", Map.of("item", "coffee")));
        Eventually.await("the platform hears the end", () -> heard.contains("ended plan-1: brought a cup of coffee"));
        assertThat(heard).startsWith("started plan-1");
        assertThat(kb.value("feedback_scout_bring", "status")).contains(Value.of("ended"));
        assertThat(kb.value("signal_scout_sonar", "value")).contains(Value.of(0.5));
    }

    /**
     * Actions whose feedback frame names would be one ('fetch tea' and 'fetch_tea' both make
     * 'feedback_scout_fetch_tea'): the second is refused, naming both, rather than overwrite the first's feedback.
     */
    @Test
    void command_whoseFeedbackFrameHoldsAnotherAction_isRefusedNamingBoth() {
        connect(new org.kicnp.example.TeaRobot(options("scout", AgentKind.ROBOT)));
        UserAgent alice = user("alice");
        CommandTicket first = alice.command("scout", "fetch tea", Map.of());
        assertThatThrownBy(() -> first.result(WAIT)).isInstanceOf(ActionFailedException.class);
        assertThat(kb.value("feedback_scout_fetch_tea", "action")).contains(Value.of("fetch tea"));

        assertThatThrownBy(() -> alice.command("scout", "fetch_tea", Map.of()))
                .isInstanceOfSatisfying(RequestRefusedException.class,
                        e -> assertThat(e.code()).isEqualTo(ErrorCode.REJECTED))
                .hasMessageMatching("Command '[^']+' to 'scout' was not sent: the feedback of action 'fetch_tea' would "
                        + "go to frame 'feedback_scout_fetch_tea', which holds the feedback of action 'fetch tea' of "
                        + "robot 'scout'; rename one of the two actions\\.");
        assertThat(kb.value("feedback_scout_fetch_tea", "action")).contains(Value.of("fetch tea"));
        assertThat(alice.command("scout", "fetch tea", Map.of())).isNotNull(); // the first action goes on as before
    }

    @Test
    void knowledge_queryAskAssert_andSubscriptionNotifies() {
        UserAgent alice = user("alice");
        UserAgent bob = user("bob");
        alice.subscribe("Cup");
        bob.assertFrame(Frame.instance("cup1", "Cup")
                .slot(org.kicnp.core.Slot.ofValue("content", org.kicnp.core.DataType.STRING, Value.of("tea"))).build());
        Eventually.await("alice hears of cup1", () -> !alice.changes().isEmpty());
        assertThat(alice.changes().getFirst()).satisfies(c -> {
            assertThat(c.change()).isEqualTo(ChangeKind.ADDED);
            assertThat(c.name()).isEqualTo("cup1");
        });
        assertThat(alice.query("Cup")).extracting(Frame::name).containsExactly("cup1");
        assertThat(alice.ask("cup1", "content")).contains(Value.of("tea"));

        bob.destroy("cup1");
        Eventually.await("alice hears cup1 go", () -> alice.changes().size() == 2);
        assertThat(alice.changes().get(1).change()).isEqualTo(ChangeKind.REMOVED);
        assertThatThrownBy(() -> alice.ask("cup1", "content")).isInstanceOfSatisfying(RequestRefusedException.class,
                e -> assertThat(e.code()).isEqualTo(ErrorCode.UNKNOWN_FRAME));
    }

    @Test
    void queryAndNotifications_carryAListsItemTypeFromTheClass_soItemsComeBackAsTheyAre() {
        kb.add(Frame.classFrame("Tray").slot(org.kicnp.core.Slot.builder("weights", org.kicnp.core.DataType.LIST)
                .argument("TYPE_FLOAT").build()).build());
        UserAgent alice = user("alice");
        alice.subscribe("Tray");
        Value weights = new Value.Lst(List.of(Value.of(1.5), Value.of(0.25)));
        // The instance's slot names no ARGUMENT of its own: its items are floats because its class says so.
        kb.add(Frame.instance("tray1", "Tray").provenance(org.kicnp.core.Provenance.RUNTIME)
                .slot(org.kicnp.core.Slot.ofValue("weights", org.kicnp.core.DataType.LIST, weights)).build());

        assertThat(alice.query("Tray")).singleElement().satisfies(f ->
                assertThat(f.ownSlot("weights").flatMap(org.kicnp.core.Slot::value)).contains(weights));
        Eventually.await("alice hears of tray1", () -> !alice.changes().isEmpty());
        List<Frame> heard = org.kicnp.protocol.FrameText.parse(alice.changes().getFirst().frame().orElseThrow(),
                "notification", KnowledgeBase.create());
        assertThat(heard).singleElement().satisfies(f ->
                assertThat(f.ownSlot("weights").flatMap(org.kicnp.core.Slot::value)).contains(weights));
    }

    @Test
    void queryAndSubscribe_ofAnInstance_andAskOfASlotNoFrameDeclares_areRefusedInWords() {
        UserAgent alice = user("alice");
        kb.add(Frame.classFrame("Mug").parent("Cup")
                .slot(org.kicnp.core.Slot.builder("content", org.kicnp.core.DataType.STRING).build()).build());
        alice.assertFrame(Frame.instance("mug1", "Mug").build());

        // Each would have answered nothing, for good: an instance has no instances, a slot no frame declares no value.
        assertThatThrownBy(() -> alice.query("mug1")).isInstanceOfSatisfying(RequestRefusedException.class,
                e -> assertThat(e.code()).isEqualTo(ErrorCode.REJECTED))
                .hasMessageContaining("Frame 'mug1' is an instance; query takes a class");
        assertThatThrownBy(() -> alice.subscribe("mug1")).isInstanceOf(RequestRefusedException.class)
                .hasMessageContaining("Frame 'mug1' is an instance; subscribe takes a class");
        assertThatThrownBy(() -> alice.ask("mug1", "colour")).isInstanceOf(RequestRefusedException.class)
                .hasMessageContaining("Frame 'mug1' has no slot 'colour', of its own or inherited.");
        assertThat(alice.ask("mug1", "content")).as("declared, without a value").isEmpty();
    }

    @Test
    void register_putsCapabilitiesAndPresence_whichGoWithTheAgent() {
        org.kicnp.example.TeaRobot scout = connect(new org.kicnp.example.TeaRobot(options("scout", AgentKind.ROBOT)));
        assertThat(kb.contains("BringTea")).isTrue();
        assertThat(kb.value("agent_scout", "capabilities")).contains(new Value.Lst(List.of(Value.of("BringTea"))));
        scout.close();
        Eventually.await("presence retracted", () -> !kb.contains("agent_scout"));
        assertThat(server.registeredAgents()).isEmpty();
    }

    @Test
    void hello_withWrongToken_failsTheAgentWithAuthenticationException() {
        UserAgent mallory = new UserAgent(options("alice", AgentKind.USER).withToken("guess"));
        open.add(mallory);
        assertThatThrownBy(() -> mallory.startAndAwait(WAIT)).isInstanceOf(AuthenticationException.class)
                .hasMessage("Server refused agent 'alice': Unknown agent 'alice' or wrong token.");
    }

    /** An unknown name and a known name with a wrong token get one answer, so a stranger cannot probe for names. */
    @Test
    void hello_withUnknownName_andWithWrongToken_getTheSameRefusal() throws IOException {
        for (String name : List.of("alice", "eve")) {
            try (RawClient raw = new RawClient(server.port())) {
                raw.send(new Message.Hello("1", name, AgentKind.USER, "guess"));
                assertThat(raw.readUntilClosed()).containsExactly(new Message.AuthResult("1", false, "kicnp",
                        Optional.of("Unknown agent '" + name + "' or wrong token.")));
            }
        }
    }

    /**
     * The platform may command a robot the moment it is registered: its presence instance, asserted while the register
     * is handled, can make a behavior frame fire at once (the paper's "Mouth" frame, activated when Robovie connects).
     * That command must reach the robot after the answer to its register, which an agent waits for before it reads
     * anything else: before, it could come first, and an SDK waiting for that answer passed it by.
     */
    @Test
    void register_aCommandSentTheMomentTheRobotIsPresent_comesAfterTheRegistersAnswer() throws IOException {
        kb.addListener(changes -> changes.events().forEach(e -> { // on the thread that asserted the presence
            if (e instanceof org.kicnp.core.FrameEvent.Added a && a.name().equals("agent_scout")) {
                server.actionSink().send(new Command("c1", "scout", "wave", Map.of()));
            }
        }));
        try (RawClient raw = new RawClient(server.port())) {
            raw.send(new Message.Hello("1", "scout", AgentKind.ROBOT, "scout-token"));
            raw.send(new Message.Register("2", List.of()));

            assertThat(raw.read()).isInstanceOf(Message.AuthResult.class);
            assertThat(raw.read()).isEqualTo(new Message.Ack("2"));
            assertThat(raw.read()).isEqualTo(new Command("c1", "scout", "wave", Map.of()));
        }
    }

    @Test
    void messageBeforeHello_getsErrorAndClose() throws IOException {
        try (RawClient raw = new RawClient(server.port())) {
            raw.send(new Message.Query("1", "Cup"));
            assertThat(raw.readUntilClosed()).singleElement().isInstanceOfSatisfying(Message.ErrorReply.class,
                    e -> assertThat(e.code()).isEqualTo(ErrorCode.NOT_AUTHENTICATED));
        }
    }

    @Test
    void secondConnection_ofSameAgent_supersedesTheFirst_andKeepsPresence() throws IOException {
        try (RawClient first = new RawClient(server.port()); RawClient second = new RawClient(server.port())) {
            for (RawClient c : List.of(first, second)) {
                c.send(new Message.Hello("1", "bob", AgentKind.USER, "bob-token"));
                c.send(new Message.Register("2", List.of()));
                assertThat(c.read()).isInstanceOf(Message.AuthResult.class);
                assertThat(c.read()).isEqualTo(new Message.Ack("2"));
            }
            assertThat(first.readUntilClosed()).last().isInstanceOfSatisfying(Message.ErrorReply.class,
                    e -> assertThat(e.code()).isEqualTo(ErrorCode.SUPERSEDED));
            assertThat(kb.contains("agent_bob")).isTrue();
            assertThat(server.registeredAgents()).containsExactly("bob");
        }
    }

    @Test
    void disconnect_inTheMiddleOfAnAction_failsItWithReason() {
        AgentBase stuck = connect(new AgentBase(options("scout", AgentKind.ROBOT)) {
            @Override protected void onCommand(Command c, ActionHandle h) {
                h.started(); // and never ends
            }
        });
        UserAgent alice = user("alice");
        CommandTicket ticket = alice.command("scout", "walk", Map.of());
        server.actionSink().send(new Command("plan-2", "scout", "walk", Map.of()));
        Eventually.await("started", () -> heard.contains("started plan-2") && ticket.feedback().size() == 1);

        stuck.close();
        Eventually.await("the platform hears the failure", () -> heard.contains("failed plan-2: agent 'scout' disconnected"));
        assertThatThrownBy(() -> ticket.result(WAIT)).isInstanceOf(ActionFailedException.class)
                .hasMessage("agent 'scout' disconnected");
        assertThat(server.commandsInFlight()).isZero();
    }

    @Test
    void malformedInput_closesOnlyThatConnection() throws IOException {
        UserAgent alice = user("alice");
        List<ErrorCode> codes = new ArrayList<>();
        byte[] oversize = new byte[8];
        java.nio.ByteBuffer.wrap(oversize).putInt(2 * 1024 * 1024);
        for (byte[] bytes : List.of("GET / HTTP/1.1\r\n\r\n".getBytes(UTF_8), oversize)) {
            try (RawClient raw = new RawClient(server.port())) {
                raw.sendBytes(bytes);
                codes.add(((Message.ErrorReply) raw.readUntilClosed().getFirst()).code());
            }
        }
        for (String json : List.of("{not json", "{\"v\":1,\"type\":\"warp\"}")) {
            try (RawClient raw = new RawClient(server.port())) {
                raw.send(new Message.Hello("1", "bob", AgentKind.USER, "bob-token"));
                assertThat(raw.read()).isInstanceOf(Message.AuthResult.class);
                raw.sendPayload(json.getBytes(UTF_8));
                codes.add(((Message.ErrorReply) raw.readUntilClosed().getFirst()).code());
            }
        }
        assertThat(codes).containsExactly(ErrorCode.FRAME_TOO_LARGE, ErrorCode.FRAME_TOO_LARGE, ErrorCode.BAD_JSON,
                ErrorCode.UNKNOWN_TYPE);
        assertThat(alice.isConnected()).isTrue();
        assertThat(alice.query("Cup")).isEmpty();
        assertThat(server.metrics().protocolErrors()).isEqualTo(4);
    }

    @Test
    void agent_reconnectsAndResubscribes_afterServerRestart() {
        UserAgent alice = user("alice");
        alice.subscribe("Cup");
        int port = server.port();
        server.close();
        Eventually.await("alice notices", () -> !alice.isConnected());

        KnowledgeBase kb2 = KnowledgeBase.create();
        kb2.add(Frame.classFrame("Cup").build());
        server = GatewayServer.start(GatewayConfig.defaults().withPort(port), AGENTS, kb2, FeedbackListener.NONE);
        alice.awaitConnected(WAIT);
        Eventually.await("presence on the new server", () -> kb2.contains("agent_alice"));
        java.util.concurrent.atomic.AtomicLong fill = new java.util.concurrent.atomic.AtomicLong();
        Eventually.await("subscription renewed", () -> { // each put changes cup2, until alice hears of one
            kb2.put(Frame.instance("cup2", "Cup").slot(org.kicnp.core.Slot.ofValue("ml", org.kicnp.core.DataType.INTEGER,
                    Value.of(fill.incrementAndGet()))).build());
            return alice.changes().stream().anyMatch(c -> c.name().equals("cup2"));
        });
    }

    private UserAgent user(String name) {
        return connect(new UserAgent(options(name, AgentKind.USER)));
    }

    private <A extends AgentBase> A connect(A agent) {
        open.add(agent);
        agent.startAndAwait(WAIT);
        return agent;
    }

    private AgentOptions options(String name, AgentKind kind) {
        return AgentOptions.of("127.0.0.1", server.port(), name, kind, name + "-token")
                .withBackoff(Duration.ofMillis(20), Duration.ofMillis(200));
    }

    /** Records what the platform's feedback listener hears, as sentences. */
    record Recorder(List<String> heard) implements FeedbackListener {
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
