package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.inference.InferenceEngine;

/**
 * Every operation {@code docs/editor-openapi.yaml} documents exists on the server: called as documented (logged
 * in, a JSON body for writes), none answers "no such resource" (404 from the router) or "method not allowed".
 */
class OpenApiDocumentTest {
    private static final Pattern PATH = Pattern.compile("^  (/api/\\S*):\\s*$");
    private static final Pattern METHOD = Pattern.compile("^    (get|post|put|delete):\\s*$");

    record Operation(String method, String path) {
    }

    static List<Operation> documented() throws IOException {
        Path yaml = Path.of(System.getProperty("user.dir")).resolve("../docs/editor-openapi.yaml").normalize();
        List<Operation> out = new ArrayList<>();
        String path = null;
        for (String line : Files.readAllLines(yaml)) {
            Matcher p = PATH.matcher(line);
            Matcher m = METHOD.matcher(line);
            if (p.matches()) {
                path = p.group(1);
            } else if (m.matches() && path != null) {
                out.add(new Operation(m.group(1).toUpperCase(Locale.ROOT), path));
            } else if (!line.startsWith(" ") && !line.isBlank()) {
                path = null;
            }
        }
        return out;
    }

    @Test void everyDocumentedOperation_isServed() throws IOException {
        List<Operation> operations = documented();
        assertThat(operations).hasSizeGreaterThan(22);
        KnowledgeBase kb = SampleKnowledge.create();
        try (InferenceEngine engine = InferenceEngine.builder(kb).build();
                EditorServer server = EditorServer.start(EditorConfig.defaults().withPort(0).withPassword("pw"), kb,
                        engine, new TestPlatform().ports())) {
            Http http = new Http(server.port());
            http.login("pw");
            for (Operation op : operations) {
                String path = op.path().replace("{name}", "Robot").replace("{instance}", "Robot")
                        .replace("{robot}", "scout").replace("{id}", "c9")
                        + (op.path().equals("/api/inference/ask") ? "?class=Robot" : "");
                HttpRequest.Builder b = http.jsonRequest(path);
                HttpRequest.BodyPublisher body = HttpRequest.BodyPublishers.ofString("{}");
                b.method(op.method(), op.method().equals("GET") || op.method().equals("DELETE")
                        ? HttpRequest.BodyPublishers.noBody() : body);
                if (op.path().equals("/api/logout")) {
                    continue;
                }

                HttpResponse<String> r = http.send(b);

                assertThat(r.statusCode()).as(op + " -> " + r.body()).isNotEqualTo(405);
                assertThat(r.body()).as(op.toString()).doesNotContain("There is no API resource");
            }
        }
    }
}
