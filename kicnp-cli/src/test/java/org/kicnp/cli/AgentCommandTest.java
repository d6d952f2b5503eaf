package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.agent.ActionHandle;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.Change;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.gateway.AgentDirectory;
import org.kicnp.gateway.FeedbackListener;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.GatewayServer;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.Message.Command;

/** {@code kicnp agent} against a real gateway on loopback, with real agents on the other end. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AgentCommandTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    @TempDir Path dir;
    private KnowledgeBase kb;
    private GatewayServer server;
    private Path tokens;

    @BeforeEach
    void start() throws Exception {
        kb = KnowledgeBase.create();
        kb.apply(List.of(
                new Change.Add(Frame.classFrame("Person").slot(Slot.builder("name", DataType.STRING).build()).build()),
                new Change.Add(Frame.instance("ken", "Person")
                        .slot(Slot.ofValue("name", DataType.STRING, Value.of("Ken"))).build())));
        AgentDirectory agents = AgentDirectory.empty()
                .with("director", "director-secret", AgentKind.USER)
                .with("listener", "listener-secret", AgentKind.USER)
                .with("scout", "scout-secret", AgentKind.ROBOT);
        tokens = Files.write(dir.resolve("agents.properties"), List.of(
                "director.token = director-secret", "director.kinds = user",
                "intruder.token = wrong-secret"));
        server = GatewayServer.start(GatewayConfig.defaults().withPort(0), agents, kb, FeedbackListener.NONE);
    }

    @AfterEach
    void stop() {
        server.close();
    }

    private CliRun agent(String... args) {
        String[] all = new String[args.length + 5];
        all[0] = "agent";
        all[1] = "--gateway";
        all[2] = "127.0.0.1:" + server.port();
        all[3] = "--tokens";
        all[4] = tokens.toString();
        System.arraycopy(args, 0, all, 5, args.length);
        return CliRun.of(all);
    }

    private AgentOptions options(String name, AgentKind kind) {
        return AgentOptions.of("127.0.0.1", server.port(), name, kind, name + "-secret");
    }

    @Test
    void query_printsEachInstanceInThePapersXml_andAsk_printsASlotsValue() {
        CliRun q = agent("query", "Person");
        assertThat(q.exitCode()).as(q.err()).isZero();
        assertThat(q.out()).contains("<NAME>ken</NAME>").contains("<ISA>Person</ISA>").contains("Ken");
        assertThat(q.err()).contains("1 instance of 'Person'.");

        CliRun a = agent("ask", "ken", "name");
        assertThat(a.exitCode()).isZero();
        assertThat(a.out().strip()).isEqualTo("Ken");

        CliRun none = agent("ask", "Person", "name");
        assertThat(none.exitCode()).isEqualTo(1);
        assertThat(none.err()).contains("'Person' has no value in slot 'name'.");
    }

    @Test
    void query_ofAnUnknownClass_exits1WithTheServersReason() {
        CliRun q = agent("query", "Robot");

        assertThat(q.exitCode()).isEqualTo(1);
        assertThat(q.err()).contains("kicnp agent query: There is no frame named 'Robot'.");
    }

    @Test
    void assert_takesASlotsTypeFromTheServersClass_andDestroy_removesTheInstance() {
        // No TYPE in the slot: the server's class says name is a string, as a knowledge file would be read.
        String xml = "<FRAME><NAME>ann</NAME><ISA>Person</ISA><ISINSTANCE>TRUE</ISINSTANCE><SLOTLIST><SLOT>"
                + "<NAME>name</NAME><VALUE>Ann</VALUE></SLOT></SLOTLIST></FRAME>";

        CliRun a = agent("assert", xml);

        assertThat(a.exitCode()).as(a.err()).isZero();
        assertThat(a.out()).contains("Asserted 'ann' (Person).");
        assertThat(kb.frame("ann")).hasValueSatisfying(f -> {
            assertThat(f.provenance()).isEqualTo(Provenance.RUNTIME);
            assertThat(f.ownSlot("name").flatMap(Slot::value)).contains(Value.of("Ann"));
        });

        CliRun d = agent("destroy", "ann");
        assertThat(d.exitCode()).as(d.err()).isZero();
        assertThat(d.out()).contains("Destroyed 'ann'.");
        assertThat(kb.contains("ann")).isFalse();
    }

    @Test
    void assert_ofAFileWithAnXmlMistake_sendsNothing_andNamesTheFileAndLine() throws Exception {
        Path file = Files.writeString(dir.resolve("people.xml"), """
                <KNOWLEDGEBASE>
                <FRAME><NAME>bob</NAME><ISA>Person</ISA><ISINSTANCE>TRUE</ISINSTANCE><SLOTLIST></SLOTLIST></FRAME>
                <FRAME><NAME>eve</NAME><ISA>Person</ISA><ISINSTANCE>MAYBE</ISINSTANCE><SLOTLIST></SLOTLIST></FRAME>
                </KNOWLEDGEBASE>
                """);

        CliRun a = agent("assert", file.toString());

        assertThat(a.exitCode()).isEqualTo(1);
        assertThat(a.err()).contains("kicnp agent assert: ").contains("people.xml:3").contains("MAYBE");
        assertThat(kb.contains("bob")).as("nothing is sent when a frame cannot be read").isFalse();
    }

    @Test
    void assert_ofSeveralFrames_isAllOrNone_atTheServer() throws Exception {
        Path good = Files.writeString(dir.resolve("good.xml"), """
                <KNOWLEDGEBASE>
                <FRAME><NAME>bob</NAME><ISA>Person</ISA><ISINSTANCE>TRUE</ISINSTANCE><SLOTLIST></SLOTLIST></FRAME>
                <FRAME><NAME>amy</NAME><ISA>Person</ISA><ISINSTANCE>TRUE</ISINSTANCE><SLOTLIST></SLOTLIST></FRAME>
                </KNOWLEDGEBASE>
                """);
        // 'ken' is declared knowledge: the server refuses the batch, and 'eve' before it is not stored either.
        Path refused = Files.writeString(dir.resolve("refused.xml"), """
                <KNOWLEDGEBASE>
                <FRAME><NAME>eve</NAME><ISA>Person</ISA><ISINSTANCE>TRUE</ISINSTANCE><SLOTLIST></SLOTLIST></FRAME>
                <FRAME><NAME>ken</NAME><ISA>Person</ISA><ISINSTANCE>TRUE</ISINSTANCE><SLOTLIST></SLOTLIST></FRAME>
                </KNOWLEDGEBASE>
                """);

        CliRun ok = agent("assert", good.toString());
        assertThat(ok.exitCode()).as(ok.err()).isZero();
        assertThat(ok.out()).contains("Asserted 'bob' (Person).").contains("Asserted 'amy' (Person).");
        assertThat(kb.contains("bob") && kb.contains("amy")).isTrue();

        CliRun no = agent("assert", refused.toString());
        assertThat(no.exitCode()).isEqualTo(1);
        assertThat(no.err()).contains("kicnp agent assert: Frame 'ken' is declared knowledge");
        assertThat(no.out()).doesNotContain("Asserted");
        assertThat(kb.contains("eve")).isFalse();
        assertThat(kb.require("ken").provenance()).isEqualTo(Provenance.DECLARED);
    }

    @Test
    void assert_ofAClass_isAUsageMistakeNamingIt() {
        CliRun a = agent("assert", "<FRAME><NAME>Robot</NAME><ISA>NULL</ISA><ISINSTANCE>FALSE</ISINSTANCE>"
                + "<SLOTLIST></SLOTLIST></FRAME>");

        assertThat(a.exitCode()).isEqualTo(1);
        assertThat(a.err()).contains("'Robot'").contains("is a class; assert takes instance frames.");
        assertThat(kb.contains("Robot")).isFalse();
    }

    @Test
    void watch_printsEachChangeOfTheClassAsAJsonLine() throws Exception {
        CompletableFuture<CliRun> watching = CompletableFuture.supplyAsync(() ->
                agent("watch", "Person", "--count", "2", "--for", "30"));
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        // Changes are made only once the watcher's subscription is in place (it is registered as 'director').
        while (!server.registeredAgents().contains("director") && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        Thread.sleep(300);
        kb.apply(List.of(new Change.Add(Frame.instance("joe", "Person").provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("name", DataType.STRING, Value.of("Joe"))).build())));
        kb.apply(List.of(new Change.Remove("joe")));

        CliRun w = watching.get(30, TimeUnit.SECONDS);

        assertThat(w.exitCode()).as(w.err()).isZero();
        List<String> lines = w.outLines();
        assertThat(lines).hasSize(2);
        JsonNode added = JSON.readTree(lines.get(0));
        assertThat(added.get("event").asText()).isEqualTo("added");
        assertThat(added.get("class").asText()).isEqualTo("Person");
        assertThat(added.get("name").asText()).isEqualTo("joe");
        assertThat(added.at("/slots/name").asText()).isEqualTo("Joe");
        assertThat(JSON.readTree(lines.get(1)).get("event").asText()).isEqualTo("removed");
    }

    @Test
    void watch_replacedByAnotherConnectionUnderItsName_stopsSayingSo() throws Exception {
        CompletableFuture<CliRun> watching = CompletableFuture.supplyAsync(() -> agent("watch", "Person", "--for", "30"));
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!server.registeredAgents().contains("director") && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        try (UserAgent second = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "director", AgentKind.USER,
                "director-secret"))) {
            second.startAndAwait(Duration.ofSeconds(10));

            CliRun w = watching.get(20, TimeUnit.SECONDS);

            assertThat(w.exitCode()).isEqualTo(1);
            assertThat(w.err()).contains("kicnp agent watch: ").contains("registered again from a new connection")
                    .contains("watch as another agent of the agent file (--as)");
        }
    }

    @Test
    void send_relaysToTheNamedAgent() {
        try (UserAgent listener = new UserAgent(options("listener", AgentKind.USER))) {
            listener.startAndAwait(Duration.ofSeconds(10));

            CliRun s = agent("send", "listener", "greeting", "hello there");

            assertThat(s.exitCode()).as(s.err()).isZero();
            assertThat(s.out()).contains("Relayed to 'listener'.");
            awaitTrue(() -> !listener.relays().isEmpty());
            assertThat(listener.relays().getFirst().from()).isEqualTo("director");
            assertThat(listener.relays().getFirst().subject()).isEqualTo("greeting");
            assertThat(listener.relays().getFirst().body()).isEqualTo("hello there");
        }
    }

    @Test
    void send_toAKindWithNoAgentOfItConnected_exits1SayingNobodyReceivedIt_andToAKindWithOne_relays() {
        CliRun none = agent("send", "--kind", "robot", "greeting", "hello there");

        assertThat(none.exitCode()).isEqualTo(1);
        assertThat(none.err()).contains("kicnp agent send: No other agent of kind 'robot' is registered, so nobody "
                + "received the relay.").doesNotContain("Exception").doesNotContain("\tat ");
        assertThat(none.out()).isEmpty();

        try (UserAgent scout = new UserAgent(options("scout", AgentKind.ROBOT))) {
            scout.startAndAwait(Duration.ofSeconds(10));

            CliRun s = agent("send", "--kind", "robot", "greeting", "hello there");

            assertThat(s.exitCode()).as(s.err()).isZero();
            assertThat(s.out()).contains("Relayed to every robot agent.");
            awaitTrue(() -> !scout.relays().isEmpty());
            assertThat(scout.relays().getFirst().subject()).isEqualTo("greeting");
        }
    }

    @Test
    void send_toAnAgentNotConnected_exits1NamingIt() {
        CliRun s = agent("send", "listener", "greeting", "hello there");

        assertThat(s.exitCode()).isEqualTo(1);
        assertThat(s.err()).contains("kicnp agent send: No agent 'listener' is registered.")
                .doesNotContain("Exception").doesNotContain("\tat ");
        assertThat(s.out()).isEmpty();
    }

    @Test
    void command_printsTheRobotsFeedback_andExits0WhenTheActionEnds_1WhenItFails() throws Exception {
        try (AgentBase scout = new AgentBase(options("scout", AgentKind.ROBOT)) {
            @Override protected void onCommand(Command c, ActionHandle h) {
                if (c.action().equals("bring")) {
                    h.started();
                    h.ended("brought " + c.args().get("item"));
                } else {
                    h.failed("cannot " + c.action());
                }
            }
        }) {
            scout.startAndAwait(Duration.ofSeconds(10));

            CliRun ok = agent("command", "scout", "bring", "item=tea");

            assertThat(ok.exitCode()).as(ok.err()).isZero();
            List<String> lines = ok.outLines();
            assertThat(lines).hasSize(2);
            assertThat(JSON.readTree(lines.get(0)).get("stage").asText()).isEqualTo("started");
            JsonNode ended = JSON.readTree(lines.get(1));
            assertThat(ended.get("stage").asText()).isEqualTo("ended");
            assertThat(ended.get("detail").asText()).isEqualTo("brought tea");

            CliRun failed = agent("command", "scout", "fly");
            assertThat(failed.exitCode()).isEqualTo(1);
            assertThat(JSON.readTree(failed.outLines().getLast()).get("detail").asText()).isEqualTo("cannot fly");

            CliRun badArg = agent("command", "scout", "bring", "tea");
            assertThat(badArg.exitCode()).isEqualTo(2);
            assertThat(badArg.err()).contains("Argument 'tea' is not NAME=VALUE.");
        }
    }

    @Test
    void proveWhyAndWhyNot_onAGatewayWithoutAnEngine_sayThereIsNone() {
        CliRun prove = agent("prove", "Person");
        assertThat(prove.exitCode()).isEqualTo(1);
        assertThat(prove.err()).contains("kicnp agent prove: This server runs no inference engine, so it cannot "
                + "prove or explain.");
        // A binding of a slot that holds no instances is refused before any reasoning.
        CliRun byName = agent("prove", "Person", "name=ken");
        assertThat(byName.exitCode()).isEqualTo(1);
        assertThat(byName.err()).contains("kicnp agent prove: Slot 'name' of class 'Person' holds TYPE_STR values, "
                + "not instances");

        CliRun why = agent("why", "ken");
        assertThat(why.exitCode()).isEqualTo(1);
        assertThat(why.err()).contains("kicnp agent why: This server runs no inference engine");

        CliRun unknown = agent("why", "nobody");
        assertThat(unknown.err()).contains("There is no frame named 'nobody'.");

        CliRun whyNot = agent("why-not", "Person");
        assertThat(whyNot.exitCode()).isEqualTo(1);
        assertThat(whyNot.err()).contains("kicnp agent why-not: This server runs no inference engine");
        CliRun badBinding = agent("why-not", "Person", "ken");
        assertThat(badBinding.exitCode()).isEqualTo(2);
        assertThat(badBinding.err()).contains("Argument 'ken' is not NAME=VALUE.");
    }

    @Test
    void whyNotsJson_carriesTheSummarySlotsAndBindings_asTheHelpSays() throws Exception {
        Message.NotFired answer = new Message.NotFired("1", "Greeting", "'Greeting' has 1 binding: 1 blocked.",
                List.of(new Message.SlotCandidates("mUser", "KnownUser", "COND_ANY", List.of("taro"), List.of(), 1, 0)),
                List.of(new Message.BindingOutcome(Map.of("mUser", "taro"), "blocked",
                        "refraction: this binding has already fired")), false);

        JsonNode json = JSON.readTree(AgentJson.pretty(AgentJson.notFired(answer)));

        assertThat(json.get("frame").asText()).isEqualTo("Greeting");
        assertThat(json.get("summary").asText()).isEqualTo("'Greeting' has 1 binding: 1 blocked.");
        assertThat(json.get("slots").get(0).get("candidates").get(0).asText()).isEqualTo("taro");
        assertThat(json.get("bindings").get(0).get("binding").get("mUser").asText()).isEqualTo("taro");
        assertThat(json.get("bindings").get(0).get("outcome").asText()).isEqualTo("blocked");
        assertThat(json.get("truncated").asBoolean()).isFalse();
    }

    @Test
    void command_thatDoesNotEndInTime_isCancelled_andCancelOfNothing_isRefused() throws Exception {
        try (AgentBase scout = new AgentBase(options("scout", AgentKind.ROBOT)) {
            @Override protected void onCommand(Command c, ActionHandle h) {
                h.started();
                while (!h.isCancelRequested()) {
                    pause();
                }
            }
        }) {
            scout.startAndAwait(Duration.ofSeconds(10));

            CliRun slow = agent("command", "scout", "walk", "--wait", "1");

            assertThat(slow.exitCode()).isEqualTo(1);
            assertThat(slow.err()).contains("Ctrl-C cancels it.").contains("did not end within 1.0 s; cancelling it.");
            assertThat(slow.outLines()).as("each report once").extracting(l -> JSON.readTree(l).get("stage").asText())
                    .containsExactly("started", "failed");
            JsonNode last = JSON.readTree(slow.outLines().getLast());
            assertThat(last.get("stage").asText()).isEqualTo("failed");
            assertThat(last.get("detail").asText())
                    .isEqualTo("cancelled: the command line stopped waiting after 1.0 s (asked by 'director')");
            assertThat(server.commandsInFlight()).isZero();

            CliRun none = agent("cancel", "scout", "director-99");
            assertThat(none.exitCode()).isEqualTo(1);
            assertThat(none.err()).contains("kicnp agent cancel: No command 'director-99' to 'scout' is in flight.");
        }
    }

    @Test
    void sensor_putsTheSignalWithItsValuesRead_repeatsItAtTheRate_andTheServerRetractsItWhenTheRunEnds()
            throws Exception {
        CompletableFuture<CliRun> run = CompletableFuture.supplyAsync(() -> agent("sensor", "obstacle", "0.4", "true",
                "7", "@ken", "near", "\"42\"", "[0.1, 2, [true], {\"ref\": \"ken\"}, \"x\"]", "--ttl", "60000",
                "--rate", "20", "--for", "3"));
        awaitTrue(() -> kb.contains("signal_director_obstacle"));
        assertThat(kb.value("signal_director_obstacle", "values")).contains(new Value.Lst(List.of(Value.of(0.4),
                Value.of(true), Value.of(7L), Value.ref("ken"), Value.of("near"), Value.of("42"),
                new Value.Lst(List.of(Value.of(0.1), Value.of(2L), new Value.Lst(List.of(Value.of(true))),
                        Value.ref("ken"), Value.of("x"))))));
        assertThat(kb.value("signal_director_obstacle", "value")).contains(Value.of(0.4));
        assertThat(kb.value("signal_director_obstacle", "expires")).isPresent();
        long first = kb.revision("signal_director_obstacle");
        awaitTrue(() -> kb.contains("signal_director_obstacle") && kb.revision("signal_director_obstacle") > first);

        CliRun r = run.get(30, TimeUnit.SECONDS);
        assertThat(r.exitCode()).as(r.err()).isZero();
        assertThat(r.err()).contains("Sent signal_director_obstacle 20.0 times a second; stopping in 3.0 s");
        awaitTrue(() -> !kb.contains("signal_director_obstacle"));
    }

    @Test
    void sensor_withoutARate_sendsTheSignalOnce_andHoldsItUntilTheRunEnds() throws Exception {
        CompletableFuture<CliRun> run = CompletableFuture.supplyAsync(() -> agent("sensor", "door", "open",
                "--for", "2"));
        awaitTrue(() -> kb.contains("signal_director_door"));
        long first = kb.revision("signal_director_door");
        Thread.sleep(1_000);
        assertThat(kb.contains("signal_director_door") && kb.revision("signal_director_door") == first)
                .as("sent once: the reading was not replaced").isTrue();

        CliRun r = run.get(30, TimeUnit.SECONDS);
        assertThat(r.exitCode()).as(r.err()).isZero();
        assertThat(r.err()).contains("Sent signal_director_door; stopping in 2.0 s");
        awaitTrue(() -> !kb.contains("signal_director_door"));
    }

    @Test
    void malformedOptionsAndArguments_areUsageErrors_exit2_namingWhatIsWrong() {
        record Case(List<String> args, String says) { }
        List<Case> cases = List.of(
                new Case(List.of("--timeout", "NaN", "query", "Person"),
                        "--timeout must be a number of seconds above 0, not NaN."),
                new Case(List.of("--timeout", "0", "query", "Person"),
                        "--timeout must be a number of seconds above 0, not 0.0."),
                new Case(List.of("watch", "Person", "--for", "NaN"),
                        "--for must be a number of seconds above 0, not NaN."),
                new Case(List.of("command", "scout", "walk", "--wait", "0"),
                        "--wait must be a number of seconds above 0, not 0.0."),
                new Case(List.of("command", "scout", "walk", "--wait=-5"),
                        "--wait must be a number of seconds above 0, not -5.0."),
                new Case(List.of("command", "", "walk"),
                        "ROBOT '' is not an agent name: use letters, digits, '_' and '-', starting with a letter or '_'."),
                new Case(List.of("command", "scout", " "), "ACTION is empty; name the action to send to 'scout'."),
                new Case(List.of("cancel", "my robot", "director-1"), "ROBOT 'my robot' is not an agent name"),
                new Case(List.of("sensor", "sonar", "1", "--ttl", "0"), "--ttl must be 1 to 86400000 milliseconds, not 0."),
                new Case(List.of("sensor", "sonar", "1", "--rate", "0"),
                        "--rate must be above 0 and at most 1000 a second, not 0.0."),
                new Case(List.of("sensor", "sonar", "1", "--for", "-1"),
                        "--for must be a number of seconds above 0, not -1.0."),
                new Case(List.of("sensor", "sonar", "[1, 2", "--for", "1"),
                        "VALUE '[1, 2' starts a list but is not a JSON array"),
                new Case(List.of("sensor", "sonar", "[null]", "--for", "1"),
                        "VALUE '[null]' holds null, which is no slot value"),
                new Case(List.of("sensor", "no spaces", "1", "--for", "1"),
                        "SENSOR 'no spaces' is not a sensor name: use letters, digits, '_' and '-'"));
        for (Case c : cases) {
            CliRun r = agent(c.args().toArray(String[]::new));
            assertThat(r.exitCode()).as(c.args() + ": " + r.err()).isEqualTo(2);
            assertThat(r.err()).as(c.args().toString()).contains(c.says()).doesNotContain("Exception");
        }

        for (String gateway : List.of("localhost:99999", "localhost:", "localhost", ":" + server.port())) {
            CliRun r = CliRun.of("agent", "--gateway", gateway, "--tokens", tokens.toString(), "query", "Person");
            assertThat(r.exitCode()).as(gateway + ": " + r.err()).isEqualTo(2);
            assertThat(r.err()).contains("--gateway '" + gateway + "' is not HOST:PORT with a port from 1 to 65535.")
                    .doesNotContain("Exception");
        }
    }

    @Test
    void gateway_mayBeAnIpv6AddressInBrackets() {
        CliRun r = CliRun.of("agent", "--gateway", "[::1]:1", "--tokens", tokens.toString(), "--timeout", "0.5",
                "query", "Person");

        // Not a usage error: the address is read, and nothing listens there.
        assertThat(r.exitCode()).as(r.err()).isEqualTo(1);
        assertThat(r.err()).contains("was not registered with ::1:1");
    }

    @Test
    void assert_ofOneFrameInTwoArguments_sendsNothing_andNamesBothPlaces() {
        String ann = "<FRAME><NAME>ann</NAME><ISA>Person</ISA><ISINSTANCE>TRUE</ISINSTANCE><SLOTLIST></SLOTLIST></FRAME>";

        CliRun a = agent("assert", ann, ann);

        assertThat(a.exitCode()).isEqualTo(1);
        assertThat(a.err()).contains("kicnp agent assert: Frame 'ann' is given twice, at argument 1:1:1 and at "
                + "argument 2:1:1; nothing was sent.");
        assertThat(kb.contains("ann")).isFalse();
    }

    @Test
    void command_afterAnEarlierRunsCommandIsStillInFlight_isSentUnderAnIdOfItsOwn() throws Exception {
        try (AgentBase scout = new AgentBase(options("scout", AgentKind.ROBOT)) {
            @Override protected void onCommand(Command c, ActionHandle h) {
                h.started(); // walks on, and cannot be stopped
            }

            @Override protected void onCancel(ActionHandle h, String reason) {
            }
        }) {
            scout.startAndAwait(Duration.ofSeconds(10));

            CliRun first = agent("command", "scout", "walk", "--wait", "0.2");
            CliRun second = agent("command", "scout", "walk", "--wait", "0.2");

            assertThat(first.err()).contains("sent to 'scout'");
            assertThat(second.err()).as("the first run's command is still in flight").contains("sent to 'scout'")
                    .doesNotContain("already in flight");
            assertThat(server.commandsInFlight()).isEqualTo(2);
        }
    }

    @Test
    void aWrongToken_isRefusedByTheServer_exit1() {
        CliRun r = agent("--as", "intruder", "query", "Person");

        assertThat(r.exitCode()).isEqualTo(1);
        assertThat(r.err()).contains("kicnp agent query: Server refused agent 'intruder': Unknown agent 'intruder' or "
                + "wrong token.\n");
        assertThat(server.registeredAgents()).doesNotContain("intruder");
    }

    @Test
    void anAgentMissingFromTheFile_orNoFile_isAUsageError() {
        CliRun missing = agent("--as", "nobody", "query", "Person");
        assertThat(missing.exitCode()).isEqualTo(2);
        assertThat(missing.err()).contains("has no 'nobody.token'.");

        CliRun noFile = CliRun.of("agent", "--tokens", dir.resolve("none.properties").toString(), "query", "Person");
        assertThat(noFile.exitCode()).isEqualTo(2);
        assertThat(noFile.err()).contains("There is no agent file").contains("none.properties");
    }

    @Test
    void noServerThere_exits1SayingSoWithinTheTimeout() throws Exception {
        int port = server.port();
        server.close();

        CliRun r = CliRun.of("agent", "--gateway", "127.0.0.1:" + port, "--tokens", tokens.toString(),
                "--timeout", "1", "query", "Person");

        assertThat(r.exitCode()).isEqualTo(1);
        assertThat(r.err()).contains("was not registered with 127.0.0.1:" + port);
    }

    private static void awaitTrue(java.util.function.BooleanSupplier condition) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!condition.getAsBoolean() && System.nanoTime() < deadline) {
            pause();
        }
        assertThat(condition.getAsBoolean()).isTrue();
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
