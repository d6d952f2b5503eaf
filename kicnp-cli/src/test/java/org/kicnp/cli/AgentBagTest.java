package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.time.InstantSource;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.cli.platform.Platform;
import org.kicnp.cli.platform.PlatformConfig;
import org.kicnp.core.Change;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameEvent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.gateway.AgentDirectory;
import org.kicnp.gateway.FeedbackListener;
import org.kicnp.gateway.GatewayConfig;
import org.kicnp.gateway.GatewayServer;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.MessageCodec;

/**
 * {@code kicnp agent record} and {@code play} against a real gateway on loopback: what the recording holds, line by
 * line; a recording played back makes the server hear the same signals; a hand-written one played into the platform
 * makes its rules fire and, when a removal or an expiry is played, withdraw what they derived.
 */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class AgentBagTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String HEADER = "{\"format\":\"kicnp-bag\",\"version\":1,\"started\":\"2026-11-27T10:00:00Z\","
            + "\"gateway\":\"127.0.0.1:7777\",\"classes\":[\"SensorSignal\"]}";
    @TempDir Path dir;
    private KnowledgeBase kb;
    private GatewayServer server;
    private AgentDirectory agents;
    private Path tokens;

    @BeforeEach
    void start() throws IOException {
        kb = KnowledgeBase.create();
        kb.apply(List.of(
                new Change.Add(Frame.classFrame("SensorSignal").build()),
                new Change.Add(Frame.classFrame("Person").slot(Slot.builder("name", DataType.STRING).build()).build()),
                new Change.Add(Frame.instance("ken", "Person").build())));
        agents = AgentDirectory.empty()
                .with("director", "director-secret", AgentKind.USER)
                .with("listener", "listener-secret", AgentKind.USER)
                .with("scout", "scout-secret", AgentKind.ROBOT);
        tokens = Files.write(dir.resolve("agents.properties"), List.of(
                "director.token = director-secret", "director.kinds = user",
                "listener.token = listener-secret", "listener.kinds = user",
                "scout.token = scout-secret", "scout.kinds = robot"));
        server = GatewayServer.start(GatewayConfig.defaults().withPort(0), agents, kb, FeedbackListener.NONE);
    }

    @AfterEach
    void stop() {
        server.close();
    }

    /**
     * Runs {@code kicnp agent --gateway … --tokens … ARGS} in-process with writers of its own, so that a recording
     * and the commands it records can run side by side (CliRun takes over System.out, one run at a time).
     */
    private CliRun agent(int port, Path agentFile, String... args) {
        List<String> all = new ArrayList<>(List.of("agent", "--gateway", "127.0.0.1:" + port, "--tokens",
                agentFile.toString()));
        all.addAll(List.of(args));
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = Main.commandLine().setOut(new PrintWriter(out, true)).setErr(new PrintWriter(err, true))
                .execute(all.toArray(String[]::new));
        return new CliRun(code, out.toString(), err.toString());
    }

    private CliRun agent(String... args) {
        return agent(server.port(), tokens, args);
    }

    private static List<String> lines(Path file) {
        try {
            return Files.exists(file) ? Files.readAllLines(file) : List.of();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** A recording's lines after the header, each without its time; the times are checked to go forward. */
    private static List<String> withoutTimes(List<String> lines) throws IOException {
        List<String> out = new ArrayList<>();
        long last = 0;
        for (String line : lines.subList(1, lines.size())) {
            ObjectNode o = (ObjectNode) JSON.readTree(line);
            assertThat(o.get("t").isIntegralNumber()).as(line).isTrue();
            assertThat(o.get("t").asLong()).as("times go forward: " + line).isGreaterThanOrEqualTo(last);
            last = o.get("t").asLong();
            o.remove("t");
            out.add(o.toString());
        }
        return out;
    }

    /** Records SensorSignal (or the classes given) as 'listener' until {@code count} lines are written. */
    private CompletableFuture<CliRun> recording(Path bag, int count, String... classes) {
        List<String> args = new ArrayList<>(List.of("--as", "listener", "record", "--out", bag.toString(), "--count",
                String.valueOf(count), "--for", "60"));
        args.addAll(List.of(classes));
        CompletableFuture<CliRun> run = CompletableFuture.supplyAsync(() -> agent(args.toArray(String[]::new)));
        // The header is written once the subscription is in place.
        awaitTrue(() -> !lines(bag).isEmpty() || run.isDone());
        assertThat(run).isNotDone();
        return run;
    }

    @Test
    void record_writesEachSignalTyped_withItsTimeToLive_andEachRemoval_andPlay_makesTheServerHearThemAgain()
            throws Exception {
        Path bag = dir.resolve("run.jsonl");
        CompletableFuture<CliRun> recording = recording(bag, 7);
        try (UserAgent scout = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "scout", AgentKind.ROBOT,
                "scout-secret"))) {
            scout.startAndAwait(Duration.ofSeconds(10));
            Value list = new Value.Lst(List.of(Value.of(0.1), Value.of(2L), new Value.Lst(List.of(Value.of(true))),
                    Value.ref("ken"), Value.of("x")));
            scout.sensor("sonar", Duration.ofMinutes(1), Value.of(0.4), Value.of(true), Value.of(7L), Value.ref("ken"),
                    Value.of("near"), Value.of("42"), list);
            awaitTrue(() -> kb.contains("signal_scout_sonar"));
            scout.sensor("sonar", Value.of(0.9));
            awaitTrue(() -> kb.value("signal_scout_sonar", "value").equals(Optional.of(Value.of(0.9))));
            CliRun sensor = agent("sensor", "door", "open", "--for", "1"); // as director, through the CLI
            assertThat(sensor.exitCode()).as(sensor.err()).isZero();
            awaitTrue(() -> lines(bag).size() == 5);
            scout.sensor("bump", Duration.ofMillis(300), Value.of(true));
            awaitTrue(() -> lines(bag).size() == 7);
        } // scout leaves: its sonar signal is retracted
        CliRun r = recording.get(30, TimeUnit.SECONDS);

        assertThat(r.exitCode()).as(r.err()).isZero();
        assertThat(r.err()).contains("Recording SensorSignal to " + bag + " as 'listener'.")
                .contains("Recorded 7 lines to " + bag + ".");
        List<String> lines = lines(bag);
        JsonNode header = JSON.readTree(lines.getFirst());
        assertThat(header.get("format").asText()).isEqualTo("kicnp-bag");
        assertThat(header.get("version").asInt()).isEqualTo(1);
        assertThat(Instant.parse(header.get("started").asText())).isBetween(Instant.now().minusSeconds(60), Instant.now());
        assertThat(header.get("gateway").asText()).isEqualTo("127.0.0.1:" + server.port());
        assertThat(header.get("classes").toString()).isEqualTo("[\"SensorSignal\"]");
        List<String> expected = List.of(
                "{\"event\":\"added\",\"agent\":\"scout\",\"sensor\":\"sonar\",\"values\":[0.4,true,7,{\"ref\":\"ken\"},"
                        + "\"near\",\"42\",[0.1,2,[true],{\"ref\":\"ken\"},\"x\"]],\"ttlMs\":60000}",
                "{\"event\":\"replaced\",\"agent\":\"scout\",\"sensor\":\"sonar\",\"values\":[0.9]}",
                "{\"event\":\"added\",\"agent\":\"director\",\"sensor\":\"door\",\"values\":[\"open\"]}",
                "{\"event\":\"removed\",\"agent\":\"director\",\"sensor\":\"door\"}",
                "{\"event\":\"added\",\"agent\":\"scout\",\"sensor\":\"bump\",\"values\":[true],\"ttlMs\":300}",
                "{\"event\":\"removed\",\"agent\":\"scout\",\"sensor\":\"bump\"}",
                "{\"event\":\"removed\",\"agent\":\"scout\",\"sensor\":\"sonar\"}");
        assertThat(withoutTimes(lines)).containsExactlyElementsOf(expected);
        long bumpAdded = JSON.readTree(lines.get(5)).get("t").asLong();
        long bumpGone = JSON.readTree(lines.get(6)).get("t").asLong();
        assertThat(bumpGone - bumpAdded).as("it expired after its 300 ms").isBetween(200L, 5_000L);

        // Played back (each signal as the agent that sent it), recorded again: the server heard the same signals.
        Path again = dir.resolve("again.jsonl");
        CompletableFuture<CliRun> second = recording(again, 7);
        CliRun play = agent("play", bag.toString());
        assertThat(play.exitCode()).as(play.err()).isZero();
        assertThat(play.out()).matches("Played 4 signals and 3 removals as 2 agents \\(scout, director\\) in "
                + "\\d+\\.\\d s\\.\\R");
        CliRun r2 = second.get(30, TimeUnit.SECONDS);
        assertThat(r2.exitCode()).as(r2.err()).isZero();
        assertThat(withoutTimes(lines(again))).containsExactlyElementsOf(expected);
    }

    @Test
    void record_startsWithTheSignalsAlreadyThere_atTimeZero_withWhatIsLeftOfTheirTimeToLive_andPlay_recreatesThem()
            throws Exception {
        Path bag = dir.resolve("state.jsonl");
        CompletableFuture<CliRun> recording;
        try (UserAgent scout = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "scout", AgentKind.ROBOT,
                "scout-secret"))) {
            scout.startAndAwait(Duration.ofSeconds(10));
            scout.sensor("sonar", Duration.ofMinutes(1), Value.of(0.4), Value.of(7L), Value.ref("ken"), Value.of("42"));
            scout.sensor("door", Value.of("open"));
            awaitTrue(() -> kb.contains("signal_scout_sonar") && kb.contains("signal_scout_door"));
            recording = recording(bag, 1);
            scout.sensor("door", Value.of("shut"));
            awaitTrue(() -> lines(bag).size() == 4);
        }
        CliRun r = recording.get(30, TimeUnit.SECONDS);

        assertThat(r.exitCode()).as(r.err()).isZero();
        assertThat(r.err()).contains("2 signals there at the start recorded at t=0.")
                .contains("Recorded 1 line to " + bag + ".");
        List<String> lines = lines(bag);
        assertThat(JSON.readTree(lines.get(1)).get("t").asLong()).isZero();
        assertThat(JSON.readTree(lines.get(2)).get("t").asLong()).isZero();
        long ttl = JSON.readTree(lines.get(2)).get("ttlMs").asLong();
        assertThat(ttl).as("what was left of its minute").isBetween(30_000L, 60_000L);
        List<String> expected = List.of(
                "{\"event\":\"added\",\"agent\":\"scout\",\"sensor\":\"door\",\"values\":[\"open\"]}",
                "{\"event\":\"added\",\"agent\":\"scout\",\"sensor\":\"sonar\",\"values\":[0.4,7,{\"ref\":\"ken\"},"
                        + "\"42\"],\"ttlMs\":" + ttl + "}",
                "{\"event\":\"replaced\",\"agent\":\"scout\",\"sensor\":\"door\",\"values\":[\"shut\"]}");
        assertThat(withoutTimes(lines)).containsExactlyElementsOf(expected);

        // scout has left, so its signals are gone; played back, the bag recreates them first, then the change.
        awaitTrue(() -> kb.instancesOf("SensorSignal").isEmpty());
        Path again = dir.resolve("again.jsonl");
        CompletableFuture<CliRun> second = recording(again, 3);
        CliRun play = agent("play", bag.toString());
        assertThat(play.exitCode()).as(play.err()).isZero();
        CliRun r2 = second.get(30, TimeUnit.SECONDS);
        assertThat(r2.exitCode()).as(r2.err()).isZero();
        assertThat(withoutTimes(lines(again))).containsExactlyElementsOf(expected);
    }

    /**
     * The time to live left of a signal there at the start is reckoned on the server's clock, the clock of its
     * {@code expires}, not on the recorder's: with the server's clock an hour behind this machine's (two machines whose
     * clocks disagree), what was left of a minute is still under a minute — on this machine's clock it would have
     * been long gone (1 ms) — while this machine's clock, moved another hour away, changes nothing.
     */
    @Test
    void record_reckonsWhatIsLeftOfATimeToLiveOnTheServersClock_notOnThisMachines() throws Exception {
        server.close();
        server = GatewayServer.start(GatewayConfig.defaults().withPort(0)
                .withClock(InstantSource.offset(Clock.systemUTC(), Duration.ofHours(-1))), agents, kb,
                FeedbackListener.NONE);
        AgentBag.wallClock = () -> System.currentTimeMillis() + Duration.ofHours(1).toMillis();
        Path bag = dir.resolve("skewed.jsonl");
        try (UserAgent scout = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "scout", AgentKind.ROBOT,
                "scout-secret"))) {
            scout.startAndAwait(Duration.ofSeconds(10));
            scout.sensor("sonar", Duration.ofMinutes(1), Value.of(0.4));
            awaitTrue(() -> kb.contains("signal_scout_sonar"));
            CompletableFuture<CliRun> recording = recording(bag, 1);
            scout.sensor("door", Duration.ofSeconds(20), Value.of("open"));
            awaitTrue(() -> lines(bag).size() == 3);
            CliRun r = recording.get(30, TimeUnit.SECONDS);
            assertThat(r.exitCode()).as(r.err()).isZero();
            assertThat(r.err()).doesNotContain("does not say its clock");
        } finally {
            AgentBag.wallClock = System::currentTimeMillis;
        }

        List<String> lines = lines(bag);
        assertThat(JSON.readTree(lines.get(1)).get("sensor").asText()).isEqualTo("sonar");
        assertThat(JSON.readTree(lines.get(1)).get("ttlMs").asLong()).as("what was left of its minute")
                .isBetween(30_000L, 60_000L);
        assertThat(JSON.readTree(lines.get(2)).get("ttlMs").asLong()).as("a signal heard: its own time to live")
                .isEqualTo(20_000L);
    }

    @Test
    void record_ofAnotherClass_keepsItsFramesAsXml_onceEach_evenWhenTwoRecordedClassesHoldThem() throws Exception {
        kb.add(Frame.classFrame("Staff").parent("Person").build());
        Path bag = dir.resolve("people.jsonl");
        CompletableFuture<CliRun> recording = recording(bag, 2, "Person", "Staff");

        kb.apply(List.of(new Change.Add(Frame.instance("joe", "Staff").provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("name", DataType.STRING, Value.of("Joe"))).build())));
        kb.apply(List.of(new Change.Remove("joe")));
        CliRun r = recording.get(30, TimeUnit.SECONDS);

        assertThat(r.exitCode()).as(r.err()).isZero();
        List<String> lines = lines(bag);
        assertThat(JSON.readTree(lines.getFirst()).get("classes").toString()).isEqualTo("[\"Person\",\"Staff\"]");
        List<String> changes = withoutTimes(lines);
        assertThat(changes).hasSize(2);
        JsonNode added = JSON.readTree(changes.get(0));
        assertThat(added.get("event").asText()).isEqualTo("added");
        assertThat(added.get("instance").asText()).isEqualTo("joe");
        assertThat(added.get("class").asText()).isEqualTo("Staff");
        assertThat(added.get("frame").asText()).contains("<NAME>joe</NAME>").contains("Joe");
        assertThat(changes.get(1)).isEqualTo("{\"event\":\"removed\",\"instance\":\"joe\"}");
    }

    @Test
    void record_asAnAgentThatIsReplaced_stopsSayingSo_andKeepsWhatItWrote() throws Exception {
        Path bag = dir.resolve("cut.jsonl");
        CompletableFuture<CliRun> recording = recording(bag, 100);
        try (UserAgent second = new UserAgent(AgentOptions.of("127.0.0.1", server.port(), "listener", AgentKind.USER,
                "listener-secret"))) {
            second.startAndAwait(Duration.ofSeconds(10));
            CliRun r = recording.get(30, TimeUnit.SECONDS);

            assertThat(r.exitCode()).isEqualTo(1);
            assertThat(r.err()).contains("kicnp agent record: ").contains("registered again from a new connection")
                    .contains("record as another agent of the agent file (--as)");
            assertThat(Bag.read(bag).lines()).isEmpty(); // the header alone, readable
        }
    }

    @Test
    void play_ofAHandWrittenRecording_makesTheRulesFire_andAPlayedRemovalOrExpiry_withdrawsWhatTheyDerived()
            throws Exception {
        Path kbDir = Files.createDirectories(dir.resolve("kb"));
        Files.writeString(kbDir.resolve("rules.xml"), """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>SensorSignal</NAME><ISINSTANCE>FALSE</ISINSTANCE><SLOTLIST>
                    <SLOT><NAME>source</NAME><TYPE>TYPE_STR</TYPE></SLOT>
                    <SLOT><NAME>sensor</NAME><TYPE>TYPE_STR</TYPE></SLOT>
                    <SLOT><NAME>time</NAME><TYPE>TYPE_INT</TYPE></SLOT>
                    <SLOT><NAME>values</NAME><TYPE>TYPE_LIST</TYPE></SLOT>
                  </SLOTLIST></FRAME>
                  <FRAME><NAME>ObstacleNear</NAME><ISINSTANCE>FALSE</ISINSTANCE><SLOTLIST>
                    <SLOT><NAME>mSignal</NAME><TYPE>TYPE_INSTANCE</TYPE><CONDITION>.value &lt; 0.5</CONDITION>
                      <ARGUMENT>SensorSignal</ARGUMENT><REQUIRED>TRUE</REQUIRED></SLOT>
                  </SLOTLIST></FRAME>
                </KNOWLEDGEBASE>
                """);
        // aibo's near reading expires after 1 s; scout's is withdrawn at 3 s while scout stays connected (its door
        // signal comes at 5 s); a far reading fires nothing.
        Path bag = Files.write(dir.resolve("hand.jsonl"), List.of(HEADER,
                "{\"t\":0,\"event\":\"added\",\"agent\":\"scout\",\"sensor\":\"sonar\",\"values\":[0.3]}",
                "{\"t\":0,\"event\":\"added\",\"agent\":\"aibo\",\"sensor\":\"sonar\",\"values\":[0.2],\"ttlMs\":1000}",
                "{\"t\":100,\"event\":\"added\",\"agent\":\"aibo\",\"sensor\":\"ear\",\"values\":[0.9]}",
                "{\"t\":200,\"event\":\"added\",\"instance\":\"ObstacleNear-9\",\"class\":\"ObstacleNear\"}",
                "{\"t\":3000,\"event\":\"removed\",\"agent\":\"scout\",\"sensor\":\"sonar\"}",
                "{\"t\":5000,\"event\":\"added\",\"agent\":\"scout\",\"sensor\":\"door\",\"values\":[\"open\"]}"));
        try (Platform platform = Platform.start(PlatformConfig.of(kbDir).withEphemeralPorts())) {
            KnowledgeBase live = platform.kb();
            CompletableFuture<CliRun> play = CompletableFuture.supplyAsync(() -> agent(platform.gatewayPort(),
                    platform.agentsFile(), "play", bag.toString()));

            awaitTrue(() -> derivedFrom(live, "signal_scout_sonar") && derivedFrom(live, "signal_aibo_sonar")
                    && live.contains("signal_aibo_ear"));
            assertThat(live.instancesOf("ObstacleNear")).as("the far reading fires nothing").hasSize(2);
            awaitTrue(() -> !live.contains("signal_aibo_sonar") && !derivedFrom(live, "signal_aibo_sonar"));
            assertThat(derivedFrom(live, "signal_scout_sonar")).as("scout's reading has no time to live").isTrue();
            awaitTrue(() -> !live.contains("signal_scout_sonar"));
            assertThat(live.contains("agent_scout")).as("withdrawn by the played removal, not by scout leaving")
                    .isTrue();
            awaitTrue(() -> live.instancesOf("ObstacleNear").isEmpty());
            assertThat(live.contains("ObstacleNear-9")).as("a frame line is not sent").isFalse();

            CliRun r = play.get(30, TimeUnit.SECONDS);
            assertThat(r.exitCode()).as(r.err()).isZero();
            assertThat(r.out()).matches("Played 4 signals and 1 removal as 2 agents \\(scout, aibo\\) in 5\\.\\d s; "
                    + "1 frame line not sent\\.\\R");
            assertThat(r.err()).contains("Playing " + bag + " (6 lines, recorded 2026-11-27T10:00:00Z) as scout, aibo.");
            awaitTrue(() -> !live.contains("signal_scout_door")); // play's agents left: their signals went with them
        }
    }

    private static boolean derivedFrom(KnowledgeBase kb, String signal) {
        return kb.instancesOf("ObstacleNear").stream()
                .anyMatch(f -> kb.value(f.name(), "mSignal").equals(Optional.of(Value.ref(signal))));
    }

    @Test
    void play_atARate_keepsTheSpacingDividedByIt_loops_andAsOneAgent_sendsEverythingAsIt() throws Exception {
        Path bag = Files.write(dir.resolve("slow.jsonl"), List.of(HEADER,
                "{\"t\":0,\"event\":\"added\",\"agent\":\"scout\",\"sensor\":\"sonar\",\"values\":[1]}",
                "{\"t\":2000,\"event\":\"replaced\",\"agent\":\"scout\",\"sensor\":\"sonar\",\"values\":[2]}"));
        List<Long> revisions = new java.util.concurrent.CopyOnWriteArrayList<>();
        kb.addListener(changes -> changes.events().stream().filter(e -> e.name().equals("signal_director_sonar"))
                .forEach(e -> revisions.add(System.nanoTime())));

        long start = System.nanoTime();
        CliRun r = agent("--as", "director", "play", bag.toString(), "--rate", "4", "--loop", "2");
        double took = (System.nanoTime() - start) / 1e9;

        assertThat(r.exitCode()).as(r.err()).isZero();
        // Two rounds of a 2 s recording at 4x: the last signal at 1 s; unscaled it would be 4 s.
        assertThat(took).isBetween(0.9, 3.5);
        assertThat(r.out()).matches("Played 4 signals and 0 removals as 1 agent \\(director\\) in \\d+\\.\\d s "
                + "\\(2 rounds\\)\\.\\R");
        awaitTrue(() -> revisions.size() >= 5); // 4 puts, then the retraction when play disconnected
        assertThat((revisions.get(1) - revisions.get(0)) / 1e9).as("2 s at 4x").isBetween(0.3, 1.5);
    }

    /**
     * From a server that does not say its clock in its answer to a query (one from before 'frames' had 'time'), the
     * recorder falls back on this machine's clock and says so. The server here is a socket speaking the protocol.
     */
    @Test
    void record_fromAServerThatDoesNotSayItsClock_saysSo_andRecordsAsBefore() throws Exception {
        MessageCodec codec = new MessageCodec();
        try (ServerSocket old = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            Thread.ofVirtual().start(() -> {
                try (Socket s = old.accept()) {
                    DataInputStream in = new DataInputStream(s.getInputStream());
                    DataOutputStream out = new DataOutputStream(s.getOutputStream());
                    while (true) {
                        Message m = codec.decode(Framing.read(in, 1 << 20));
                        Message answer = switch (m) {
                            case Message.Hello h -> new Message.AuthResult(h.id(), true, "old", Optional.empty());
                            case Message.Query q -> new Message.Frames(q.id(), List.of(), Optional.empty());
                            case Message.Request r -> new Message.Ack(r.id());
                            default -> null;
                        };
                        if (answer != null) {
                            Framing.write(out, codec.encode(answer));
                        }
                    }
                } catch (Exception ignored) {
                    // the recorder has gone
                }
            });
            Path bag = dir.resolve("old.jsonl");
            CliRun r = agent(old.getLocalPort(), tokens, "--as", "listener", "record", "--out", bag.toString(),
                    "--for", "1");

            assertThat(r.exitCode()).as(r.err()).isZero();
            assertThat(r.err()).contains("The server does not say its clock (it predates 'frames' with 'time'): the "
                    + "times to live of the signals there at the start are reckoned on this machine's clock.")
                    .contains("Recorded 0 lines to " + bag + ".");
            assertThat(lines(bag)).hasSize(1); // the header
        }
    }

    /**
     * Lines of two agents recorded in one millisecond reach the server in their recorded order, though each agent
     * sends on a connection of its own (which the server reads on either of its I/O threads): before a line goes
     * through another agent than the last signal's, play waits until the server has taken that signal.
     */
    @Test
    void play_keepsTheRecordedOrder_acrossAgents_evenWithinOneMillisecond() throws Exception {
        int count = 80;
        List<String> lines = new ArrayList<>(List.of(HEADER));
        for (int i = 0; i < count; i++) {
            lines.add("{\"t\":0,\"event\":\"added\",\"agent\":\"" + (i % 2 == 0 ? "director" : "scout")
                    + "\",\"sensor\":\"tick\",\"values\":[" + i + "]}");
        }
        Path bag = Files.write(dir.resolve("burst.jsonl"), lines);
        List<Long> heard = new java.util.concurrent.CopyOnWriteArrayList<>();
        kb.addListener(changes -> changes.events().stream()
                .filter(e -> e.name().startsWith("signal_") && !(e instanceof FrameEvent.Removed))
                .forEach(e -> heard.add(
                        ((Value.Int) e.frame().ownSlot("value").orElseThrow().value().orElseThrow()).value())));

        CliRun r = agent("play", bag.toString());

        assertThat(r.exitCode()).as(r.err()).isZero();
        assertThat(heard).as("the order the server took them in")
                .containsExactlyElementsOf(java.util.stream.LongStream.range(0, count).boxed().toList());
    }

    @Test
    void play_ofABadFile_isAUsageErrorNamingTheFileAndLine_andSendsNothing() throws Exception {
        String good = "{\"t\":0,\"event\":\"added\",\"agent\":\"scout\",\"sensor\":\"sonar\",\"values\":[1]}";
        record Case(List<String> lines, String says) { }
        List<Case> cases = List.of(
                new Case(List.of(HEADER, good, "{\"t\":5,\"event\":\"added\","), ":3: the line is not JSON"),
                new Case(List.of(good), ":1: the first line is not a header of a kicnp-bag"),
                new Case(List.of(HEADER.replace("\"version\":1", "\"version\":2"), good),
                        ":1: the bag's version is 2; this kicnp reads version 1."),
                new Case(List.of(HEADER, good.replace("[1]", "[null]")), ":2: 'values' holds null, which is no slot value"),
                new Case(List.of(HEADER, good.replace("\"t\":0", "\"t\":9"), good),
                        ":3: 't' 0 is before the 9 of the line above: times must not go back."),
                new Case(List.of(HEADER, good, good.replace("added", "moved")),
                        ":3: 'event' must be added, replaced or removed, not 'moved'."),
                new Case(List.of(HEADER, good.replace("}", ",\"ttlMs\":0}")),
                        ":2: 'ttlMs' must be a whole number from 1 to 86400000, not 0."),
                new Case(List.of(HEADER, good.replace("\"t\":0", "\"t\":1.5")),
                        ":2: 't' (ms since the start) must be a whole number of 0 or more, not 1.5."),
                new Case(List.of(HEADER, good.replace("scout", "my robot")), ":2: 'agent' 'my robot' is not a name"),
                new Case(List.of(HEADER, "{\"t\":0,\"event\":\"added\"}"),
                        ":2: the line has neither 'sensor' (a signal) nor 'instance' (a frame)."),
                new Case(List.of(HEADER, good, good.replace("scout", "pino")),
                        "The agent file '" + tokens + "' has no 'pino.token' for agent 'pino' ("),
                new Case(List.of(), ":1: the bag is empty"));
        for (int i = 0; i < cases.size(); i++) {
            Case c = cases.get(i);
            Path bag = Files.write(dir.resolve("bad" + i + ".jsonl"), c.lines());
            CliRun r = agent("play", bag.toString());
            assertThat(r.exitCode()).as(c.says() + ": " + r.err()).isEqualTo(2);
            assertThat(r.err()).as(c.says()).contains(c.says()).doesNotContain("Exception");
            assertThat(r.err()).as("names the file").contains(bag.toString());
        }
        assertThat(agent("play", dir.resolve("bad10.jsonl").toString()).err()).contains("bad10.jsonl:3); nothing was sent.");
        assertThat(kb.instancesOf("SensorSignal")).as("nothing was sent").isEmpty();
        assertThat(server.registeredAgents()).as("nobody connected").isEmpty();

        CliRun missing = agent("play", dir.resolve("none.jsonl").toString());
        assertThat(missing.exitCode()).isEqualTo(2);
        assertThat(missing.err()).contains("There is no bag file '" + dir.resolve("none.jsonl") + "'.");
        CliRun both = agent("--as", "director", "play", dir.resolve("bad0.jsonl").toString(), "--as-recorded");
        assertThat(both.exitCode()).isEqualTo(2);
        assertThat(both.err()).contains("Give --as NAME or --as-recorded, not both.");
        for (String[] args : List.of(new String[] {"--rate", "0"}, new String[] {"--rate", "NaN"},
                new String[] {"--loop", "0"})) {
            CliRun bad = agent("play", dir.resolve("bad0.jsonl").toString(), args[0], args[1]);
            assertThat(bad.exitCode()).as(String.join(" ", args)).isEqualTo(2);
            assertThat(bad.err()).contains(args[0] + " must be");
        }
        CliRun noOut = agent("record");
        assertThat(noOut.exitCode()).isEqualTo(2);
        assertThat(noOut.err()).contains("Missing required option: '--out=FILE'");
    }

    @Test
    void record_withNoServerThere_exits1_andLeavesAnEarlierFileAsItWas() throws Exception {
        Path bag = Files.writeString(dir.resolve("earlier.jsonl"), HEADER + "\n");
        int port = server.port();
        server.close();

        CliRun r = agent(port, tokens, "--timeout", "1", "record", "--out", bag.toString());

        assertThat(r.exitCode()).isEqualTo(1);
        assertThat(r.err()).contains("kicnp agent record: ").contains("was not registered with 127.0.0.1:" + port);
        assertThat(Files.readString(bag)).isEqualTo(HEADER + "\n");
    }

    @Test
    void recordAndPlay_answerHelp() {
        CliRun record = agent("record", "--help");
        assertThat(record.exitCode()).isZero();
        assertThat(record.out()).contains("Usage: kicnp agent record").contains("--out=FILE").contains("kicnp-bag");
        CliRun play = agent("play", "--help");
        assertThat(play.exitCode()).isZero();
        assertThat(play.out()).contains("Usage: kicnp agent play").contains("--rate=FACTOR").contains("--loop=N")
                .contains("--as-recorded");
    }

    private static void awaitTrue(java.util.function.BooleanSupplier condition) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
        while (!condition.getAsBoolean() && System.nanoTime() < deadline) {
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
        assertThat(condition.getAsBoolean()).isTrue();
    }
}
