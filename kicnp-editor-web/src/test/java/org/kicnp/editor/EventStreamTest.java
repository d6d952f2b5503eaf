package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletionException;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.kicnp.core.KnowledgeBase;

import static org.assertj.core.api.Assertions.assertThatThrownBy;

/** The {@code /api/events} WebSocket against a real Jetty on an ephemeral loopback port. */
class EventStreamTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    private KnowledgeBase kb;
    private EditorServer server;

    @BeforeEach void start() {
        kb = SampleKnowledge.create();
        server = EditorServer.start(EditorConfig.defaults().withPort(0).withPassword("pw"), kb);
    }

    @AfterEach void stop() {
        server.close();
    }

    @Test void events_afterAnEditThroughTheApi_pushTheChangedFrame() throws Exception {
        BlockingQueue<String> received = new LinkedBlockingQueue<>();
        WebSocket ws = connect(received, "http://127.0.0.1:" + server.port());
        assertThat(JSON.readTree(received.poll(5, TimeUnit.SECONDS)).get("type").asText()).isEqualTo("hello");

        Http http = new Http(server.port());
        http.login("pw");
        http.post("/api/frames", "{\"name\":\"PINO\",\"kind\":\"INSTANCE\",\"parent\":\"HumanoidRobot\"}");

        JsonNode event = JSON.readTree(received.poll(5, TimeUnit.SECONDS));
        assertThat(event.get("type").asText()).isEqualTo("change");
        assertThat(event.get("version").asLong()).isEqualTo(kb.version());
        JsonNode e = event.get("events").get(0);
        assertThat(e.get("kind").asText()).isEqualTo("added");
        assertThat(e.get("name").asText()).isEqualTo("PINO");
        assertThat(e.get("frame").get("parent").asText()).isEqualTo("HumanoidRobot");
        ws.abort();
    }

    @Test void events_afterRemoval_sayRemoved() throws Exception {
        BlockingQueue<String> received = new LinkedBlockingQueue<>();
        WebSocket ws = connect(received, "http://127.0.0.1:" + server.port());
        received.poll(5, TimeUnit.SECONDS);

        kb.remove("Taro");

        JsonNode e = JSON.readTree(received.poll(5, TimeUnit.SECONDS)).get("events").get(0);
        assertThat(e.get("kind").asText()).isEqualTo("removed");
        assertThat(e.get("name").asText()).isEqualTo("Taro");
        ws.abort();
    }

    @Test void events_fromAnotherOrigin_areRefused() {
        assertThatThrownBy(() -> connect(new LinkedBlockingQueue<>(), "http://evil.example"))
                .isInstanceOf(CompletionException.class);
    }

    private WebSocket connect(BlockingQueue<String> received, String origin) {
        return HttpClient.newHttpClient().newWebSocketBuilder().header("Origin", origin)
                .buildAsync(URI.create("ws://127.0.0.1:" + server.port() + "/api/events"), new WebSocket.Listener() {
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
