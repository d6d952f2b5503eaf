package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.Change;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message;

/**
 * {@code kicnp agent} against a real gateway on loopback, with real agents on the other end: the commands on the
 * server's knowledge ({@code query}, {@code ask}, {@code assert}, {@code destroy}, {@code watch}) and on its
 * reasoning ({@code prove}, {@code why}, {@code why-not}).
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AgentCommandTest extends AgentCommandFixture {
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
    void assert_ofOneFrameInTwoArguments_sendsNothing_andNamesBothPlaces() {
        String ann = "<FRAME><NAME>ann</NAME><ISA>Person</ISA><ISINSTANCE>TRUE</ISINSTANCE><SLOTLIST></SLOTLIST></FRAME>";

        CliRun a = agent("assert", ann, ann);

        assertThat(a.exitCode()).isEqualTo(1);
        assertThat(a.err()).contains("kicnp agent assert: Frame 'ann' is given twice, at argument 1:1:1 and at "
                + "argument 2:1:1; nothing was sent.");
        assertThat(kb.contains("ann")).isFalse();
    }
}
