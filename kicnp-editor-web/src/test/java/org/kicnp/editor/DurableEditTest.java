package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.http.HttpResponse;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.core.Frame;
import org.kicnp.core.Value;
import org.kicnp.core.store.KnowledgeStore;

/** An edit saved in the editor survives a restart when the knowledge base is backed by the durable store. */
class DurableEditTest {
    @TempDir Path dir;

    @Test void edit_throughTheEditor_isThereAfterTheStoreIsReopened() {
        try (KnowledgeStore store = KnowledgeStore.open(dir)) {
            store.kb().add(Frame.classFrame("System").build());
            try (EditorServer server = EditorServer.start(EditorConfig.defaults().withPort(0).withPassword("pw"),
                    store.kb())) {
                Http http = new Http(server.port());
                http.login("pw");

                HttpResponse<String> r = http.post("/api/frames", """
                        {"name":"Robot","parent":"System","slots":[{"name":"legs","type":"TYPE_INT","value":"4"}]}""");

                assertThat(r.statusCode()).as(r.body()).isEqualTo(201);
            }
        }

        try (KnowledgeStore reopened = KnowledgeStore.open(dir)) {
            assertThat(reopened.kb().value("Robot", "legs")).contains(Value.of(4));
        }
    }
}
