package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;
import static org.kicnp.editor.EditorApiFixture.json;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.kicnp.core.KnowledgeBase;

/**
 * The World panel's API (world, chat, tele-operation, "wrong") against a real Jetty on an ephemeral loopback port,
 * with a small in-test platform behind the ports ({@link TestPlatform}), and its events over {@code /api/events}.
 */
class PlatformApiTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    private final TestPlatform platform = new TestPlatform();
    private EditorServer server;
    private Http http;

    @BeforeEach void start() {
        KnowledgeBase kb = SampleKnowledge.create();
        server = EditorServer.start(EditorConfig.defaults().withPort(0).withPassword("pw"), kb, platform.ports());
        http = new Http(server.port());
    }

    @AfterEach void stop() {
        server.close();
    }

    @Test void world_beforeTheFirstSnapshot_is204_thenTheLatestSnapshot() {
        assertThat(http.get("/api/world").statusCode()).isEqualTo(204);
        platform.publish(TestPlatform.scene(1.0));
        platform.publish(TestPlatform.scene(2.0));

        HttpResponse<String> r = http.get("/api/world");

        assertThat(r.statusCode()).isEqualTo(200);
        JsonNode world = json(r);
        assertThat(world.get("time").asDouble()).isEqualTo(2.0);
        assertThat(world.get("room").get("width").asDouble()).isEqualTo(8.0);
        assertThat(world.get("robots")).extracting(n -> n.get("name").asText()).containsExactly("robovie", "scout", "aibo");
        JsonNode scout = world.get("robots").get(1);
        assertThat(scout.get("headingDeg").asDouble()).isEqualTo(90.0);
        assertThat(scout.get("actions").get(0).get("action").asText()).isEqualTo("go_to");
        assertThat(world.get("users").get(0).get("name").asText()).isEqualTo("alice");
        assertThat(world.get("cups").get(0).get("holder").asText()).isEmpty();
    }

    @Test void session_saysWhichPortsAreConnected() {
        JsonNode session = json(http.get("/api/session"));
        assertThat(session.get("world").asBoolean()).isTrue();
        assertThat(session.get("chat").asBoolean()).isTrue();
        assertThat(session.get("teleOperation").asBoolean()).isTrue();
    }

    @Test void chat_withoutLogin_is401_andNothingIsSaid() {
        HttpResponse<String> r = http.post("/api/chat", "{\"text\":\"I want tea\"}");

        assertThat(r.statusCode()).isEqualTo(401);
        assertThat(platform.said).isEmpty();
    }

    @Test void chat_afterLogin_passesTheLineAsUserA_andKeepsTheConversation() {
        http.login("pw");

        HttpResponse<String> r = http.post("/api/chat", "{\"text\":\" I want tea \"}");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(202);
        assertThat(json(r).get("kind").asText()).isEqualTo("user");
        assertThat(platform.said).containsExactly("User A: I want tea");
        List<String> lines = new ArrayList<>();
        json(http.get("/api/chat")).get("lines").forEach(l -> lines.add(l.get("kind").asText() + " "
                + l.get("speaker").asText() + ": " + l.get("text").asText()));
        assertThat(lines).containsExactly("user User A: I want tea", "understood User A: request: bring tea to User A",
                "robot Robovie: Scout will bring you tea.");
    }

    @Test void chat_emptyLine_isRefusedInWords() {
        http.login("pw");
        HttpResponse<String> r = http.post("/api/chat", "{\"text\":\"  \"}");
        assertThat(r.statusCode()).isEqualTo(400);
        assertThat(json(r).get("error").asText()).isEqualTo("Say something: the chat line is empty.");
    }

    @Test void robots_listTheirActionsAndArguments() {
        JsonNode robots = json(http.get("/api/robots"));
        assertThat(robots).extracting(n -> n.get("name").asText()).containsExactly("robovie", "scout");
        JsonNode goTo = robots.get(1).get("actions").get(0);
        assertThat(goTo.get("name").asText()).isEqualTo("go_to");
        assertThat(goTo.get("args")).extracting(a -> a.get("name").asText() + ":" + a.get("required").asBoolean())
                .containsExactly("x:true", "y:true");
    }

    @Test void command_withoutLogin_is401_andNothingIsSent() {
        HttpResponse<String> r = http.post("/api/robots/scout/commands", "{\"action\":\"go_to\"}");
        assertThat(r.statusCode()).isEqualTo(401);
        assertThat(platform.sent).isEmpty();
    }

    @Test void command_afterLogin_isSentWithItsArguments_andListedWithItsFeedback() throws Exception {
        http.login("pw");

        HttpResponse<String> r = http.post("/api/robots/scout/commands",
                "{\"action\":\"go_to\",\"args\":{\"x\":\"7.0\",\"y\":3.5}}");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(202);
        String id = json(r).get("id").asText();
        assertThat(platform.sent).containsExactly(id + " scout go_to {x=7.0, y=3.5}");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        JsonNode row;
        do {
            Thread.sleep(20);
            row = json(http.get("/api/commands")).get(0);
        } while (!row.get("status").asText().equals("ended") && System.nanoTime() < deadline);
        assertThat(row.get("id").asText()).isEqualTo(id);
        assertThat(row.get("status").asText()).isEqualTo("ended");
        assertThat(row.get("detail").asText()).isEqualTo("done");
        assertThat(row.get("args").get("x").asText()).isEqualTo("7.0");
    }

    @Test void command_unknownAction_is422WithThePlatformsSentence() {
        http.login("pw");
        HttpResponse<String> r = http.post("/api/robots/scout/commands", "{\"action\":\"fly\"}");
        assertThat(r.statusCode()).isEqualTo(422);
        assertThat(json(r).get("error").asText()).isEqualTo("Robot 'scout' has no action 'fly'.");
    }

    @Test void wrong_withoutLogin_is401_afterLoginIsPassedToThePlatform() {
        HttpResponse<String> anonymous = http.post("/api/actions/c9/wrong", "{\"reason\":\"wrong cup\"}");
        assertThat(anonymous.statusCode()).isEqualTo(401);
        assertThat(platform.judged).isEmpty();
        http.login("pw");

        HttpResponse<String> r = http.post("/api/actions/c9/wrong", "{\"reason\":\"wrong cup\"}");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        assertThat(platform.judged).containsExactly("c9: wrong cup");
        assertThat(json(http.get("/api/commands")).get(0).get("wrong").asText()).isEqualTo("wrong cup");
    }

    @Test void wrong_withoutAReason_is400_andAnUnknownAction422() {
        http.login("pw");
        assertThat(http.post("/api/actions/c9/wrong", "{}").statusCode()).isEqualTo(400);
        HttpResponse<String> unknown = http.post("/api/actions/zz/wrong", "{\"reason\":\"no\"}");
        assertThat(unknown.statusCode()).isEqualTo(422);
        assertThat(json(unknown).get("error").asText()).isEqualTo("No action 'zz' is known.");
        assertThat(platform.judged).isEmpty();
    }

    @Test void stop_withoutLogin_is401_afterLoginTheActionIsCancelled_andItsRowSaysSo() throws Exception {
        http.login("pw");
        String id = json(http.post("/api/robots/scout/commands", "{\"action\":\"patrol\"}")).get("id").asText();
        HttpResponse<String> anonymous = new Http(server.port()).post("/api/actions/" + id + "/stop",
                "{\"reason\":\"enough\"}");
        assertThat(anonymous.statusCode()).isEqualTo(401);
        assertThat(platform.stopped).isEmpty();

        HttpResponse<String> r = http.post("/api/actions/" + id + "/stop", "{\"reason\":\"enough\"}");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        assertThat(json(r).get("stop").asText()).isEqualTo("enough");
        assertThat(platform.stopped).containsExactly(id + ": enough");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        JsonNode row = json(http.get("/api/commands")).get(0);
        while (!row.get("status").asText().equals("failed") && System.nanoTime() < deadline) {
            Thread.sleep(20);
            row = json(http.get("/api/commands")).get(0);
        }
        assertThat(row.get("status").asText()).isEqualTo("failed");
        assertThat(row.get("id").asText()).isEqualTo(id);
        assertThat(row.get("detail").asText()).isEqualTo("cancelled: enough");
    }

    @Test void stop_withoutAReason_saysWhere_andAnActionNotRunningIs422() {
        http.login("pw");

        assertThat(http.post("/api/actions/c9/stop", "{}").statusCode()).isEqualTo(200);
        HttpResponse<String> again = http.post("/api/actions/c9/stop", "{}");

        assertThat(platform.stopped).containsExactly("c9: stopped in the editor");
        assertThat(again.statusCode()).isEqualTo(422);
        assertThat(json(again).get("error").asText()).isEqualTo("No action 'c9' is running.");
        assertThat(http.get("/api/actions/c9/stop").statusCode()).isEqualTo(405);
    }

    @Test void events_deliverAWorldSnapshot_aChatLine_andCommandFeedback() throws Exception {
        BlockingQueue<String> received = new LinkedBlockingQueue<>();
        WebSocket ws = connect(received, server.port());
        assertThat(JSON.readTree(received.poll(5, TimeUnit.SECONDS)).get("type").asText()).isEqualTo("hello");
        http.login("pw");

        platform.publish(TestPlatform.scene(3.5));
        JsonNode world = next(received, "world");
        http.post("/api/chat", "{\"text\":\"hello there\"}");
        JsonNode mine = next(received, "chat");
        JsonNode verdict = next(received, "chat");
        http.post("/api/robots/robovie/commands", "{\"action\":\"fail_me\"}");
        List<String> statuses = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            statuses.add(next(received, "feedback").get("status").asText());
        }

        assertThat(world.get("snapshot").get("time").asDouble()).isEqualTo(3.5);
        assertThat(world.get("snapshot").get("robots").get(0).get("name").asText()).isEqualTo("robovie");
        assertThat(mine.get("text").asText()).isEqualTo("hello there");
        assertThat(verdict.get("kind").asText()).isEqualTo("not_understood");
        assertThat(statuses).containsExactly("sent", "started", "failed");
        ws.abort();
    }

    @Test void events_manySnapshotsAtOnce_areThrottled_andTheNewestArrives() throws Exception {
        BlockingQueue<String> received = new LinkedBlockingQueue<>();
        WebSocket ws = connect(received, server.port());
        received.poll(5, TimeUnit.SECONDS);

        for (int i = 1; i <= 60; i++) {
            platform.publish(TestPlatform.scene(i));
            Thread.sleep(5);
        }
        List<Double> times = new ArrayList<>();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (!times.contains(60.0) && System.nanoTime() < deadline) {
            String m = received.poll(1, TimeUnit.SECONDS);
            if (m != null) {
                times.add(JSON.readTree(m).get("snapshot").get("time").asDouble());
            }
        }

        assertThat(times).contains(60.0);
        assertThat(times.size()).as("world events for 60 snapshots in ~0.4 s: %s", times).isBetween(2, 8);
        ws.abort();
    }

    @Test void withoutPorts_theWorldChatAndTeleOperationAnswer503InWords() {
        try (EditorServer bare = EditorServer.start(EditorConfig.defaults().withPort(0).withPassword("pw"),
                SampleKnowledge.create())) {
            Http h = new Http(bare.port());
            h.login("pw");
            List<HttpResponse<String>> answers = List.of(h.get("/api/world"), h.get("/api/chat"),
                    h.post("/api/chat", "{\"text\":\"tea\"}"), h.get("/api/robots"), h.get("/api/commands"),
                    h.post("/api/robots/scout/commands", "{\"action\":\"go_to\"}"),
                    h.post("/api/actions/c9/wrong", "{\"reason\":\"no\"}"));

            assertThat(answers).allSatisfy(r -> {
                assertThat(r.statusCode()).isEqualTo(503);
                assertThat(json(r).get("error").asText()).startsWith("This editor is not connected to a platform");
            });
            assertThat(json(h.get("/api/session")).get("world").asBoolean()).isFalse();
        }
    }

    private static JsonNode next(BlockingQueue<String> received, String type) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (System.nanoTime() < deadline) {
            String m = received.poll(100, TimeUnit.MILLISECONDS);
            if (m != null) {
                JsonNode event = JSON.readTree(m);
                if (event.get("type").asText().equals(type)) {
                    return event;
                }
            }
        }
        throw new AssertionError("No '" + type + "' event arrived within 5 seconds.");
    }

    static WebSocket connect(BlockingQueue<String> received, int port) {
        return HttpClient.newHttpClient().newWebSocketBuilder()
                .buildAsync(URI.create("ws://127.0.0.1:" + port + "/api/events"), new WebSocket.Listener() {
                    private final StringBuilder partial = new StringBuilder();

                    @Override public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
                        partial.append(data);
                        if (last) {
                            received.add(partial.toString());
                            partial.setLength(0);
                        }
                        webSocket.request(1);
                        return null;
                    }
                }).join();
    }
}
