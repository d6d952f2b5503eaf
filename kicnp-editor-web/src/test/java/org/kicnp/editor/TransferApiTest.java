package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;
import static org.kicnp.editor.EditorApiFixture.json;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.http.HttpResponse;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.kicnp.core.KnowledgeBase;

/** XML export and import, and the script check, against a real Jetty on an ephemeral loopback port. */
class TransferApiTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String PASSWORD = "pw";

    private KnowledgeBase kb;
    private EditorServer server;
    private Http http;

    @BeforeEach void start() {
        kb = SampleKnowledge.create();
        server = EditorServer.start(EditorConfig.defaults().withPort(0).withPassword(PASSWORD), kb);
        http = new Http(server.port());
    }

    @AfterEach void stop() {
        server.close();
    }

    private static String importBody(String xml) {
        return JSON.createObjectNode().put("xml", xml).toString();
    }

    @Test void export_writesEveryFrameInThePapersFormat() {
        HttpResponse<String> r = http.get("/api/export");

        assertThat(r.statusCode()).isEqualTo(200);
        assertThat(r.headers().firstValue("Content-Type")).hasValueSatisfying(t -> assertThat(t).startsWith("application/xml"));
        assertThat(r.body()).contains("<NAME>AskUserName</NAME>").contains("<ISA>Speech</ISA>")
                .contains("<TYPE>TYPE_INSTANCE</TYPE>").contains("<ARGUMENT>NewUser</ARGUMENT>");
        assertThat(http.get("/api/export?download=true").headers().firstValue("Content-Disposition"))
                .hasValueSatisfying(d -> assertThat(d).contains("attachment"));
    }

    @Test void exportThenImport_intoAnEmptyKnowledgeBase_givesTheSameFrames() {
        String xml = http.get("/api/export").body();
        KnowledgeBase empty = KnowledgeBase.create();
        try (EditorServer other = EditorServer.start(EditorConfig.defaults().withPort(0).withPassword(PASSWORD), empty)) {
            Http to = new Http(other.port());
            to.login(PASSWORD);

            HttpResponse<String> r = to.post("/api/import", importBody(xml));

            assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
            assertThat(json(r).get("count").asInt()).isEqualTo(kb.size());
            assertThat(empty.frames()).containsExactlyElementsOf(kb.frames());
        }
    }

    @Test void import_ofMalformedXml_reportsLineAndColumnAndChangesNothing() {
        http.login(PASSWORD);
        long version = kb.version();

        HttpResponse<String> r = http.post("/api/import",
                importBody("<KNOWLEDGEBASE>\n<FRAME>\n  <NAME>Broken</NAME>\n</FRAMES>"));

        assertThat(r.statusCode()).isEqualTo(422);
        JsonNode p = json(r).get("problems").get(0);
        assertThat(p.get("line").asInt()).isPositive();
        assertThat(p.get("column").asInt()).isPositive();
        assertThat(kb.version()).isEqualTo(version);
    }

    @Test void import_withOneBadFrame_importsNothingAndPlacesTheProblem() {
        http.login(PASSWORD);
        String xml = """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Scout</NAME><ISA>Robot</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                  <FRAME><NAME>AIBO</NAME><ISA>RobotDog</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                </KNOWLEDGEBASE>""";

        HttpResponse<String> r = http.post("/api/import", importBody(xml));

        assertThat(r.statusCode()).isEqualTo(422);
        assertThat(r.body()).contains("RobotDog");
        assertThat(json(r).get("problems").get(0).get("line").asInt()).isEqualTo(3);
        assertThat(kb.contains("Scout")).isFalse();
        assertThat(kb.contains("AIBO")).isFalse();
    }

    @Test void import_withMappingErrors_namesTheFrameAndSlotOfEachProblem() {
        http.login(PASSWORD);
        String xml = """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Cup</NAME><ISINSTANCE>FALSE</ISINSTANCE>
                    <SLOTLIST><SLOT><NAME>content</NAME><TYPE>TYPE_STR</TYPE><REQUIRED>maybe</REQUIRED></SLOT></SLOTLIST>
                  </FRAME>
                  <FRAME><NAME>Mug</NAME><ISINSTANCE>perhaps</ISINSTANCE></FRAME>
                  <FRAME><NAME>Cup</NAME><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                </KNOWLEDGEBASE>""";

        HttpResponse<String> r = http.post("/api/import", importBody(xml));

        assertThat(r.statusCode()).isEqualTo(422);
        JsonNode problems = json(r).get("problems");
        assertThat(problems).as(r.body()).hasSize(3);
        assertThat(problems.get(0).get("message").asText()).contains("REQUIRED 'maybe'");
        assertThat(problems.get(0).get("frame").asText()).isEqualTo("Cup");
        assertThat(problems.get(0).get("slot").asText()).isEqualTo("content");
        assertThat(problems.get(1).get("message").asText()).contains("ISINSTANCE 'perhaps'");
        assertThat(problems.get(1).get("frame").asText()).isEqualTo("Mug");
        assertThat(problems.get(1).get("slot").asText()).isEmpty();
        assertThat(problems.get(2).get("message").asText()).contains("defined twice");
        assertThat(problems.get(2).get("frame").asText()).isEqualTo("Cup");
        assertThat(problems.get(2).get("slot").asText()).isEmpty();
        assertThat(kb.contains("Mug")).isFalse();
    }

    @Test void import_withAnXmlErrorAndAFrameModelProblem_reportsBothAtOnce() {
        http.login(PASSWORD);
        String xml = """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Mug</NAME><ISINSTANCE>perhaps</ISINSTANCE></FRAME>
                  <FRAME><NAME>AIBO</NAME><ISA>RobotDog</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                </KNOWLEDGEBASE>""";

        HttpResponse<String> r = http.post("/api/import", importBody(xml));

        assertThat(r.statusCode()).isEqualTo(422);
        JsonNode problems = json(r).get("problems");
        assertThat(problems).as(r.body()).hasSize(2);
        assertThat(problems.get(0).get("frame").asText()).isEqualTo("Mug");
        assertThat(problems.get(0).get("line").asInt()).isEqualTo(2);
        assertThat(problems.get(1).get("frame").asText()).isEqualTo("AIBO");
        assertThat(problems.get(1).get("message").asText()).contains("'RobotDog', which is not defined");
        assertThat(problems.get(1).get("line").asInt()).isEqualTo(3);
        assertThat(kb.contains("AIBO")).isFalse();
    }

    @Test void import_withAScriptThatDoesNotParse_answers422AtItsFrameAndChangesNothing() {
        http.login(PASSWORD);
        long version = kb.version();
        String xml = """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Scout</NAME><ISA>Robot</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                  <FRAME><NAME>Wave</NAME><ISA>System</ISA><ISINSTANCE>FALSE</ISINSTANCE>
                    <SLOTLIST>
                      <SLOT><NAME>onInstantiate</NAME><TYPE>TYPE_STR</TYPE><VALUE>Sendmsg(s.mMouth, 'hi';</VALUE></SLOT>
                      <SLOT><NAME>arms</NAME><TYPE>TYPE_INT</TYPE><CONDITION>js: s.arms &gt;</CONDITION></SLOT>
                    </SLOTLIST>
                  </FRAME>
                </KNOWLEDGEBASE>""";

        HttpResponse<String> r = http.post("/api/import", importBody(xml));

        assertThat(r.statusCode()).as(r.body()).isEqualTo(422);
        JsonNode problems = json(r).get("problems");
        assertThat(problems).as(r.body()).hasSize(2);
        assertThat(problems.get(0).get("frame").asText() + "." + problems.get(0).get("slot").asText())
                .isEqualTo("Wave.onInstantiate");
        assertThat(problems.get(0).get("message").asText()).startsWith("The script in slot 'onInstantiate' of frame "
                + "'Wave' has a syntax error at line 1, column ");
        assertThat(problems.get(0).get("line").asInt()).isEqualTo(3);
        assertThat(problems.get(1).get("frame").asText() + "." + problems.get(1).get("slot").asText())
                .isEqualTo("Wave.arms");
        assertThat(problems.get(1).get("message").asText()).startsWith("The js: condition of slot 'arms' of frame "
                + "'Wave' has a syntax error");
        assertThat(kb.contains("Scout")).isFalse();
        assertThat(kb.contains("Wave")).isFalse();
        assertThat(kb.version()).isEqualTo(version);
    }

    @Test void import_withoutLogin_answers401() {
        HttpResponse<String> r = http.post("/api/import", importBody("<FRAMES/>"));

        assertThat(r.statusCode()).isEqualTo(401);
    }

    @Test void scriptCheck_acceptsThePapersScriptAndPointsAtASyntaxError() {
        http.login(PASSWORD);

        JsonNode good = json(http.post("/api/scripts/check", JSON.createObjectNode()
                .put("source", "Sendmsg(s.mMouth, “Hi! Nice to meet you.”);").put("name", "Greeting.onInstantiate")
                .toString()));
        JsonNode bad = json(http.post("/api/scripts/check", JSON.createObjectNode()
                .put("source", "var x = 1;\nsendmsg(s.mMouth, 'hi';").put("name", "Greeting.onInstantiate").toString()));

        assertThat(good.get("ok").asBoolean()).as(good.toString()).isTrue();
        assertThat(bad.get("ok").asBoolean()).isFalse();
        assertThat(bad.get("line").asInt()).isEqualTo(2);
        assertThat(bad.get("message").asText()).isNotBlank();
    }

    @Test void session_reportsTheFeaturesOfThisBuild() {
        JsonNode s = json(http.get("/api/session"));

        assertThat(s.get("xml").asBoolean()).isTrue();
        assertThat(s.get("scripts").asBoolean()).isTrue();
    }
}
