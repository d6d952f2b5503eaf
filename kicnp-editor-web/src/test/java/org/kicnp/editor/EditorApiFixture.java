package org.kicnp.editor;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.http.HttpResponse;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.kicnp.core.KnowledgeBase;

/**
 * What the JSON API's tests share: the sample knowledge served by a real Jetty on an ephemeral loopback port, with an
 * editor password, a client for it, and answers read as JSON.
 */
abstract class EditorApiFixture {
    private static final ObjectMapper JSON = new ObjectMapper();
    static final String PASSWORD = "correct horse";

    KnowledgeBase kb;
    EditorServer server;
    Http http;

    @BeforeEach void start() {
        kb = SampleKnowledge.create();
        server = EditorServer.start(EditorConfig.defaults().withPort(0).withPassword(PASSWORD), kb);
        http = new Http(server.port());
    }

    @AfterEach void stop() {
        server.close();
    }

    static JsonNode json(HttpResponse<String> r) {
        try {
            return JSON.readTree(r.body());
        } catch (java.io.IOException e) {
            throw new AssertionError("Not JSON: " + r.body(), e);
        }
    }
}
