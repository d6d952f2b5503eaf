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
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.inference.GraalScriptHost;
import org.kicnp.inference.InferenceEngine;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptRuntime;

/** The inference view: the paper's AskUserName fires when a NewUser and a Mouth are set up (section 4.3). */
class InferenceApiTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    private static ScriptRuntime scripts;
    private KnowledgeBase kb;
    private InferenceEngine engine;
    private EditorServer server;
    private Http http;

    @BeforeAll static void startScripts() {
        scripts = ScriptRuntime.create(ScriptConfig.defaults());
    }

    @AfterAll static void stopScripts() {
        scripts.close();
    }

    @BeforeEach void start() {
        kb = SampleKnowledge.create();
        engine = InferenceEngine.builder(kb).scripts(new GraalScriptHost(scripts)).build();
        server = EditorServer.start(EditorConfig.defaults().withPort(0).withPassword("pw"), kb, engine);
        http = new Http(server.port());
        http.login("pw");
    }

    @AfterEach void stop() {
        server.close();
        engine.close();
    }

    private void setUpUserAndMouth() {
        kb.add(Frame.instance("userA", "NewUser").provenance(Provenance.RUNTIME).build());
        kb.add(Frame.instance("mouth1", "Mouth").provenance(Provenance.RUNTIME).build());
    }

    @Test void run_firesAskUserName_andStatusListsTheDerivedInstance() {
        setUpUserAndMouth();
        JsonNode before = json(http.get("/api/inference"));
        assertThat(before.get("agenda").asInt()).isEqualTo(1);
        JsonNode waiting = before.get("activations").get(0);
        assertThat(waiting.get("frame").asText()).isEqualTo("AskUserName");
        assertThat(waiting.get("binding").get("mUser").asText()).isEqualTo("userA");
        assertThat(waiting.get("binding").get("mMouth").asText()).isEqualTo("mouth1");
        assertThat(waiting.has("priority") && waiting.has("depth") && waiting.has("recency")).isTrue();

        HttpResponse<String> run = http.post("/api/inference/run", "{}");

        assertThat(run.statusCode()).as(run.body()).isEqualTo(200);
        assertThat(json(run).get("firings").asInt()).isEqualTo(1);
        JsonNode status = json(http.get("/api/inference"));
        assertThat(status.get("agenda").asInt()).isZero();
        assertThat(status.get("activations")).isEmpty();
        List<String> derived = new ArrayList<>();
        status.get("instances").forEach(i -> {
            if (i.get("derived").asBoolean()) {
                derived.add(i.get("className").asText());
            }
        });
        assertThat(derived).containsExactly("AskUserName");
    }

    @Test void delete_ofAnInstance_goesThroughTheEngine_withWhatWasDerivedFromIt() {
        setUpUserAndMouth();
        http.post("/api/inference/run", "{}");
        String made = kb.instancesOf("AskUserName").getFirst().name();

        // The knowledge base alone refuses: AskUserName-… refers to userA. Through the engine both go.
        HttpResponse<String> deleted = http.delete("/api/frames/userA");

        assertThat(deleted.statusCode()).as(deleted.body()).isEqualTo(200);
        assertThat(json(deleted).get("removed")).extracting(JsonNode::asText).containsExactly("userA", made);
        assertThat(kb.contains("userA")).isFalse();
        assertThat(kb.contains(made)).isFalse();
        assertThat(kb.contains("mouth1")).isTrue();
    }

    @Test void askAndProve_ofAnInstance_are404SayingTheyTakeAClass() {
        setUpUserAndMouth();

        HttpResponse<String> ask = http.get("/api/inference/ask?class=userA");
        HttpResponse<String> prove = http.get("/api/inference/prove?class=userA");

        assertThat(ask.statusCode()).isEqualTo(404);
        assertThat(ask.body()).contains("Frame 'userA' is an instance; ask takes a class.");
        assertThat(prove.statusCode()).isEqualTo(404);
        assertThat(prove.body()).contains("Frame 'userA' is an instance; prove takes a class.");
    }

    @Test void why_explainsTheDerivedInstanceDownToTheStimuli() {
        setUpUserAndMouth();
        http.post("/api/inference/run", "{}");
        String made = kb.instancesOf("AskUserName").getFirst().name();

        JsonNode why = json(http.get("/api/inference/why/" + made));

        assertThat(why.get("type").asText()).isEqualTo("derived");
        assertThat(why.get("derivation").get("frame").asText()).isEqualTo("AskUserName");
        assertThat(why.get("derivation").get("binding").get("mUser").asText()).isEqualTo("userA");
        assertThat(why.get("supports")).extracting(s -> s.get("instance").asText())
                .containsExactlyInAnyOrder("userA", "mouth1");
    }

    @Test void why_ofAClass_is404_sayingWhyExplainsInstances() {
        HttpResponse<String> r = http.get("/api/inference/why/NewUser");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(404);
        assertThat(json(r).get("error").asText()).isEqualTo("Frame 'NewUser' is a class; why explains instances only.");
        assertThat(json(r).get("problems")).isEmpty();
    }

    @Test void ask_answersWhichInstancesCouldExist() {
        setUpUserAndMouth();

        JsonNode answers = json(http.get("/api/inference/ask?class=AskUserName"));

        assertThat(answers).isNotEmpty();
        assertThat(answers.get(0).get("derivable").asBoolean()).isTrue();
    }

    @Test void prove_returnsTheProofTreeWithoutCreatingAnything() {
        setUpUserAndMouth();
        int before = json(http.get("/api/frames")).size();

        JsonNode proofs = json(http.get("/api/inference/prove?class=AskUserName"));

        assertThat(proofs).isNotEmpty();
        JsonNode p = proofs.get(0);
        assertThat(p.get("kind").asText()).isEqualTo("derivable");
        assertThat(p.get("className").asText()).isEqualTo("AskUserName");
        assertThat(p.get("slots").get("mUser").get("kind").asText()).isEqualTo("exists");
        assertThat(p.get("slots").get("mUser").get("instance").asText()).isEqualTo("userA");
        assertThat(p.get("depth").asInt()).isEqualTo(1);
        assertThat(json(http.get("/api/frames")).size()).isEqualTo(before);
        assertThat(http.get("/api/inference/prove").statusCode()).isEqualTo(400);
    }

    @Test void whyNot_saysWhatStopsEachBinding_andWhichSlotHasNoCandidate_withoutCreatingAnything() {
        setUpUserAndMouth();
        http.post("/api/inference/run", "{}");
        int before = json(http.get("/api/frames")).size();

        JsonNode asked = json(http.get("/api/inference/why-not?frame=AskUserName"));

        assertThat(asked.get("summary").asText()).isEqualTo("'AskUserName' has 1 binding: 1 blocked.");
        assertThat(asked.get("slots").get(0).get("candidates").get(0).asText()).isEqualTo("userA");
        JsonNode b = asked.get("bindings").get(0);
        assertThat(b.get("binding").get("mUser").asText()).isEqualTo("userA");
        assertThat(b.get("outcome").asText()).isEqualTo("blocked");
        assertThat(b.get("reason").asText()).isEqualTo("refraction: this binding has already fired");
        assertThat(json(http.get("/api/frames")).size()).isEqualTo(before);
        assertThat(http.get("/api/inference/why-not").statusCode()).isEqualTo(400);
        assertThat(http.get("/api/inference/why-not?frame=Nope").statusCode()).isEqualTo(404);
        HttpResponse<String> notBehavior = http.get("/api/inference/why-not?frame=User");
        assertThat(notBehavior.statusCode()).isEqualTo(422);
        assertThat(notBehavior.body()).contains("Frame 'User' is not a behavior frame");
    }

    @Test void run_withoutLogin_answers401() {
        Http anonymous = new Http(server.port());

        assertThat(anonymous.post("/api/inference/run", "{}").statusCode()).isEqualTo(401);
        assertThat(anonymous.get("/api/inference").statusCode()).isEqualTo(200);
    }

    @Test void traceEvents_arriveOverTheEventStream() throws Exception {
        BlockingQueue<String> received = new LinkedBlockingQueue<>();
        WebSocket ws = HttpClient.newHttpClient().newWebSocketBuilder()
                .buildAsync(URI.create("ws://127.0.0.1:" + server.port() + "/api/events"), new WebSocket.Listener() {
                    private final StringBuilder partial = new StringBuilder();

                    @Override public CompletionStage<?> onText(WebSocket w, CharSequence data, boolean last) {
                        partial.append(data);
                        if (last) {
                            received.add(partial.toString());
                            partial.setLength(0);
                        }
                        w.request(1);
                        return null;
                    }
                }).join();
        setUpUserAndMouth();

        http.post("/api/inference/run", "{}");

        List<String> events = new ArrayList<>();
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (!events.contains("Fired") && System.nanoTime() < until) {
            String m = received.poll(100, TimeUnit.MILLISECONDS);
            if (m != null) {
                JsonNode n = JSON.readTree(m);
                if (n.get("type").asText().equals("trace")) {
                    events.add(n.get("event").asText());
                }
            }
        }
        assertThat(events).contains("Fired");
        ws.abort();
    }

    @Test void ask_tooBroadForTheEnginesLimit_is422_sayingHowToNarrowIt() {
        setUpUserAndMouth();
        kb.add(Frame.instance("userB", "NewUser").provenance(Provenance.RUNTIME).build());
        try (InferenceEngine narrow = InferenceEngine.builder(kb).options(org.kicnp.inference.EngineOptions.defaults()
                .withMaxQuestionSteps(1)).build();
             EditorServer other = EditorServer.start(EditorConfig.defaults().withPort(0), kb, narrow)) {
            var answer = new Http(other.port()).get("/api/inference/ask?class=AskUserName");

            assertThat(answer.statusCode()).isEqualTo(422);
            assertThat(json(answer).get("error").asText()).startsWith("The question about 'AskUserName' is too broad")
                    .endsWith("hold some of the slots fixed to narrow it.");
        }
        assertThat(http.get("/api/inference/ask?class=AskUserName").statusCode()).isEqualTo(200);
    }

    @Test void inference_withoutEngine_answers501AndSessionSaysSo() {
        try (EditorServer plain = EditorServer.start(EditorConfig.defaults().withPort(0), kb)) {
            Http other = new Http(plain.port());

            assertThat(other.get("/api/inference").statusCode()).isEqualTo(501);
            assertThat(json(other.get("/api/session")).get("inference").asBoolean()).isFalse();
        }
        assertThat(json(http.get("/api/session")).get("inference").asBoolean()).isTrue();
    }
}
