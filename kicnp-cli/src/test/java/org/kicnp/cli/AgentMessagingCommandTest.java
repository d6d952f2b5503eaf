package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kicnp.agent.ActionHandle;
import org.kicnp.agent.AgentBase;
import org.kicnp.agent.AgentOptions;
import org.kicnp.agent.UserAgent;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message.Command;

/**
 * {@code kicnp agent} against a real gateway on loopback, with real agents on the other end: what it sends to other
 * agents, {@code send} relays to an agent or a kind, {@code command} and {@code cancel} to a robot with its feedback
 * printed, and {@code sensor} signals put into the knowledge and retracted when the run ends.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AgentMessagingCommandTest extends AgentCommandFixture {
    private AgentOptions options(String name, AgentKind kind) {
        return AgentOptions.of("127.0.0.1", server.port(), name, kind, name + "-secret");
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
