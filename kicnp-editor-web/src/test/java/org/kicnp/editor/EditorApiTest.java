package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.net.http.HttpResponse;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Relation;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/** The JSON API against a real Jetty on an ephemeral loopback port. */
class EditorApiTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String PASSWORD = "correct horse";

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

    static JsonNode json(HttpResponse<String> r) {
        try {
            return JSON.readTree(r.body());
        } catch (java.io.IOException e) {
            throw new AssertionError("Not JSON: " + r.body(), e);
        }
    }

    @Test void list_returnsEveryFrameWithKindParentLearnedAndRevision() {
        HttpResponse<String> r = http.get("/api/frames");

        assertThat(r.statusCode()).isEqualTo(200);
        JsonNode rows = json(r);
        assertThat(rows).hasSize(kb.size());
        JsonNode robovie = find(rows, "Robovie");
        assertThat(robovie.get("kind").asText()).isEqualTo("INSTANCE");
        assertThat(robovie.get("parent").asText()).isEqualTo("HumanoidRobot");
        assertThat(robovie.get("revision").asLong()).isEqualTo(kb.revision("Robovie"));
        assertThat(find(rows, "Taro").get("learned").asBoolean()).isTrue();
        assertThat(find(rows, "System").get("parent").isNull()).isTrue();
    }

    @Test void list_givesEachFramesDeclaredLinksAsArrowsFromBothEnds() {
        kb.add(Frame.classFrame("Farewell").parent("Speech")
                .linkFrom(Relation.Coordination.SUCCESSION, "Greeting")
                .linkTo(new Relation.Named("answers"), "AskUserName").build());

        JsonNode rows = json(http.get("/api/frames"));

        assertThat(find(rows, "Greeting").get("links")).extracting(JsonNode::toString)
                .containsExactly("{\"relation\":\"SUCCESSION\",\"from\":\"Greeting\",\"to\":\"AskUserName\"}");
        assertThat(find(rows, "Farewell").get("links")).extracting(JsonNode::toString).containsExactly(
                "{\"relation\":\"answers\",\"from\":\"Farewell\",\"to\":\"AskUserName\"}",
                "{\"relation\":\"SUCCESSION\",\"from\":\"Greeting\",\"to\":\"Farewell\"}");
        assertThat(find(rows, "Robovie").get("links")).isEmpty();
        assertThat(find(rows, "Robovie").get("hasLinks").asBoolean()).isFalse();
    }

    @Test void list_withQuery_keepsOnlyMatchingNames() {
        JsonNode rows = json(http.get("/api/frames?q=user"));

        assertThat(rows).extracting(n -> n.get("name").asText())
                .containsExactlyInAnyOrder("User", "KnownUser", "NewUser", "AskUserName");
    }

    @Test void get_returnsOwnAndEffectiveSlotsWithEveryFacetAndDeclaringFrame() {
        JsonNode f = json(http.get("/api/frames/AskUserName"));

        assertThat(f.get("kind").asText()).isEqualTo("CLASS");
        assertThat(f.get("ancestors")).extracting(JsonNode::asText).containsExactly("Speech", "Behavior", "System");
        assertThat(f.get("slots")).extracting(s -> s.get("name").asText())
                .containsExactly("mUser", "mMouth", "onInstantiate");
        JsonNode mUser = f.get("slots").get(0);
        for (String facet : List.of("name", "role", "from", "type", "value", "defaultValue", "condition", "argument",
                "required", "shared", "unique", "frameRelated", "frameListRelated")) {
            assertThat(mUser.has(facet)).as("facet %s", facet).isTrue();
        }
        assertThat(mUser.get("type").asText()).isEqualTo("TYPE_INSTANCE");
        assertThat(mUser.get("argument").asText()).isEqualTo("NewUser");
        assertThat(mUser.get("condition").asText()).isEqualTo("COND_ANY");
        JsonNode inherited = find(f.get("effectiveSlots"), "mfunction");
        assertThat(inherited.get("declaredBy").asText()).isEqualTo("Speech");
        assertThat(inherited.get("inherited").asBoolean()).isTrue();
        assertThat(inherited.get("slot").get("value").asText()).isEqualTo("sendmsg");
        assertThat(json(http.get("/api/frames/Greeting")).get("linksTo").get(0).get("relation").asText())
                .isEqualTo("SUCCESSION");
        assertThat(f.get("linksIn")).extracting(l -> l.get("frame").asText()).containsExactly("Greeting");
    }

    @Test void get_ofClass_listsItsChildren() {
        JsonNode f = json(http.get("/api/frames/User"));

        assertThat(f.get("children")).extracting(c -> c.get("name").asText()).containsExactly("KnownUser", "NewUser");
    }

    @Test void get_unknownFrame_answers404WithSentence() {
        HttpResponse<String> r = http.get("/api/frames/Nobody");

        assertThat(r.statusCode()).isEqualTo(404);
        assertThat(json(r).get("error").asText()).isEqualTo("There is no frame named 'Nobody'.");
    }

    @Test void createEditDelete_whenLoggedIn_changeTheKnowledgeBase() {
        http.login(PASSWORD);

        HttpResponse<String> created = http.post("/api/frames", """
                {"name":"Scout","kind":"CLASS","parent":"Robot",
                 "slots":[{"name":"sonars","type":"TYPE_INT","value":"16","required":true}]}""");
        assertThat(created.statusCode()).as(created.body()).isEqualTo(201);
        assertThat(kb.value("Scout", "sonars")).contains(Value.of(16));

        ObjectNode body = (ObjectNode) json(created).get("frame");
        ((ObjectNode) body.get("slots").get(0)).put("value", "17");
        body.put("expectedRevision", body.get("revision").asLong());
        HttpResponse<String> saved = http.put("/api/frames/Scout", body.toString());
        assertThat(saved.statusCode()).as(saved.body()).isEqualTo(200);
        assertThat(kb.value("Scout", "sonars")).contains(Value.of(17));
        assertThat(kb.value("Scout", "battery")).contains(Value.of(100));

        HttpResponse<String> deleted = http.delete("/api/frames/Scout");
        assertThat(deleted.statusCode()).as(deleted.body()).isEqualTo(200);
        assertThat(kb.contains("Scout")).isFalse();
    }

    @Test void put_withStaleRevision_answers409AndKeepsTheOtherEdit() {
        http.login(PASSWORD);
        ObjectNode mine = (ObjectNode) json(http.get("/api/frames/Robot"));
        kb.replace(kb.require("Robot").toBuilder().priority(5).build());

        mine.put("expectedRevision", mine.get("revision").asLong());
        mine.put("priority", 9);
        HttpResponse<String> r = http.put("/api/frames/Robot", mine.toString());

        assertThat(r.statusCode()).isEqualTo(409);
        assertThat(json(r).get("error").asText()).contains("Frame 'Robot' was changed by someone else");
        assertThat(kb.require("Robot").priority()).isEqualTo(5);
    }

    @Test void put_withoutExpectedRevision_isRefused() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.put("/api/frames/Robot", "{\"kind\":\"CLASS\",\"parent\":\"System\"}");

        assertThat(r.statusCode()).isEqualTo(400);
        assertThat(json(r).get("error").asText()).contains("expectedRevision");
    }

    @Test void put_withInvalidSlots_answers422WithEveryProblemAndChangesNothing() {
        http.login(PASSWORD);
        Frame before = kb.require("AskUserName");
        ObjectNode f = forEditing("AskUserName");
        ArrayNode slots = (ArrayNode) f.get("slots");
        ((ObjectNode) slots.get(0)).put("argument", "Martian");
        ObjectNode bad = slots.addObject();
        bad.put("name", "age").put("type", "TYPE_INT").put("value", "3").put("defaultValue", "4");
        slots.addObject().put("name", "mood").put("type", "TYPE_INT").put("value", "happy");

        HttpResponse<String> r = http.put("/api/frames/AskUserName", f.toString());

        assertThat(r.statusCode()).isEqualTo(422);
        List<String> messages = new ArrayList<>();
        json(r).get("problems").forEach(p -> messages.add(p.get("slot").asText() + ": " + p.get("message").asText()));
        assertThat(messages).anySatisfy(m -> assertThat(m).startsWith("age: ").contains("both a value and a default"))
                .anySatisfy(m -> assertThat(m).startsWith("mood: ").contains("'happy' is not an integer"));
        assertThat(kb.require("AskUserName")).isEqualTo(before);

        slots.remove(slots.size() - 1);
        slots.remove(slots.size() - 1);
        HttpResponse<String> unknownClass = http.put("/api/frames/AskUserName", f.toString());
        assertThat(unknownClass.statusCode()).isEqualTo(422);
        assertThat(json(unknownClass).get("problems").get(0).get("message").asText()).contains("'Martian'");
        assertThat(json(unknownClass).get("problems").get(0).get("frame").asText()).isEqualTo("AskUserName");
        assertThat(kb.require("AskUserName")).isEqualTo(before);
    }

    @Test void put_withAValueOfTheWrongTypeAndAnUnknownArgumentClass_listsBothProblemsInOneAnswer() {
        http.login(PASSWORD);
        Frame before = kb.require("AskUserName");
        ObjectNode f = forEditing("AskUserName");
        ArrayNode slots = (ArrayNode) f.get("slots");
        ((ObjectNode) slots.get(0)).put("argument", "Martian");
        slots.addObject().put("name", "mood").put("type", "TYPE_INT").put("value", "happy");

        HttpResponse<String> r = http.put("/api/frames/AskUserName", f.toString());

        assertThat(r.statusCode()).isEqualTo(422);
        List<String> messages = new ArrayList<>();
        json(r).get("problems").forEach(p -> messages.add(p.get("frame").asText() + "." + p.get("slot").asText() + ": "
                + p.get("message").asText()));
        assertThat(messages).hasSize(2)
                .anySatisfy(m -> assertThat(m).startsWith("AskUserName.mood: ").contains("'happy' is not an integer"))
                .anySatisfy(m -> assertThat(m).startsWith("AskUserName.mUser: ").contains("'Martian'"));
        assertThat(kb.require("AskUserName")).isEqualTo(before);
    }

    @Test void post_withAFloatThatIsNaN_answers422NamingTheFrameAndSlotAndAddsNothing() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.post("/api/frames", """
                {"name": "Scale", "kind": "CLASS", "parent": "System",
                 "slots": [{"name": "ratio", "type": "TYPE_FLOAT", "value": "NaN"}]}""");

        assertThat(r.statusCode()).isEqualTo(422);
        JsonNode problem = json(r).get("problems").get(0);
        assertThat(problem.get("frame").asText() + "." + problem.get("slot").asText()).isEqualTo("Scale.ratio");
        assertThat(problem.get("message").asText()).contains("'NaN' is not a number");
        assertThat(kb.contains("Scale")).isFalse();
    }

    /** The page checks scripts before it saves; a client of the API alone must meet the same check. */
    @Test void put_withAJsConditionOrDemonThatDoesNotParse_answers422NamingFrameAndSlotAndChangesNothing() {
        http.login(PASSWORD);
        Frame before = kb.require("AskUserName");
        long version = kb.version();
        ObjectNode f = forEditing("AskUserName");
        ArrayNode slots = (ArrayNode) f.get("slots");
        ((ObjectNode) slots.get(1)).put("condition", "js: s.mMouth.on &&");
        ((ObjectNode) slots.get(0)).put("onAdded", "log(");

        HttpResponse<String> r = http.put("/api/frames/AskUserName", f.toString());

        assertThat(r.statusCode()).as(r.body()).isEqualTo(422);
        List<String> messages = new ArrayList<>();
        json(r).get("problems").forEach(p -> messages.add(p.get("frame").asText() + "." + p.get("slot").asText() + ": "
                + p.get("message").asText()));
        assertThat(messages).hasSize(2)
                .anySatisfy(m -> assertThat(m).startsWith("AskUserName.mMouth: The js: condition of slot 'mMouth' of "
                        + "frame 'AskUserName' has a syntax error at line 1, column "))
                .anySatisfy(m -> assertThat(m).startsWith("AskUserName.mUser: The onAdded demon of slot 'mUser' of "
                        + "frame 'AskUserName' has a syntax error at line 1, column "));
        assertThat(kb.require("AskUserName")).isEqualTo(before);
        assertThat(kb.version()).isEqualTo(version);
    }

    @Test void post_withAJsConditionThatDoesNotParse_answers422AndAddsNothing() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.post("/api/frames", """
                {"name": "Cook", "kind": "CLASS", "parent": "System",
                 "slots": [{"name": "dishes", "type": "TYPE_INT", "condition": "js: s.dishes >"}]}""");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(422);
        JsonNode problem = json(r).get("problems").get(0);
        assertThat(problem.get("frame").asText() + "." + problem.get("slot").asText()).isEqualTo("Cook.dishes");
        assertThat(problem.get("message").asText()).startsWith("The js: condition of slot 'dishes' of frame 'Cook' has "
                + "a syntax error");
        assertThat(kb.contains("Cook")).isFalse();
    }

    @Test void post_withAValueOfTheWrongTypeAndAnUnknownParent_listsBothProblemsInOneAnswer() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.post("/api/frames", """
                {"name": "Cook", "kind": "CLASS", "parent": "Kitchen",
                 "slots": [{"name": "dishes", "type": "TYPE_INT", "value": "many"}]}""");

        assertThat(r.statusCode()).isEqualTo(422);
        List<String> messages = new ArrayList<>();
        json(r).get("problems").forEach(p -> messages.add(p.get("slot").asText() + ": " + p.get("message").asText()));
        assertThat(messages).hasSize(2)
                .anySatisfy(m -> assertThat(m).startsWith("dishes: ").contains("'many' is not an integer"))
                .anySatisfy(m -> assertThat(m).startsWith(": ").contains("'Kitchen'"));
        assertThat(kb.contains("Cook")).isFalse();
    }

    @Test void put_withSlotsThatAreNotAnArray_answers422AndKeepsEverySlot() {
        http.login(PASSWORD);
        Frame before = kb.require("AskUserName");
        ObjectNode f = forEditing("AskUserName");
        f.put("slots", "mUser");

        HttpResponse<String> r = http.put("/api/frames/AskUserName", f.toString());

        assertThat(r.statusCode()).as(r.body()).isEqualTo(422);
        assertThat(json(r).get("problems").get(0).get("message").asText())
                .isEqualTo("Frame 'AskUserName' has slots \"mUser\", which is not an array.");
        assertThat(kb.require("AskUserName")).isEqualTo(before);
    }

    @Test void put_withParentOrConditionThatIsNotAText_answers422AndKeepsTheFrame() {
        http.login(PASSWORD);
        Frame before = kb.require("AskUserName");
        ObjectNode f = forEditing("AskUserName");
        f.putObject("parent").put("name", "Speech");
        ((ObjectNode) f.get("slots").get(0)).putArray("condition").add("== \"tea\"");

        HttpResponse<String> r = http.put("/api/frames/AskUserName", f.toString());

        assertThat(r.statusCode()).as(r.body()).isEqualTo(422);
        List<String> messages = new ArrayList<>();
        json(r).get("problems").forEach(p -> messages.add(p.get("message").asText()));
        assertThat(messages).containsExactlyInAnyOrder(
                "Frame 'AskUserName' has parent {\"name\":\"Speech\"}, which is not a text.",
                "Slot 'mUser' of frame 'AskUserName' has condition [\"== \\\"tea\\\"\"], which is not a text.");
        assertThat(kb.require("AskUserName")).isEqualTo(before);
    }

    @Test void create_withFacetThatIsNotABooleanOrPriorityThatIsNotAnInteger_answers422AndAddsNothing() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.post("/api/frames", """
                {"name":"Scout","kind":"CLASS","parent":"Robot","priority":"high",
                 "slots":[{"name":"sonars","type":"TYPE_INT","required":"maybe"}]}""");
        HttpResponse<String> huge = http.post("/api/frames", """
                {"name":"Scout","kind":"CLASS","parent":"Robot","priority":1e99}""");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(422);
        List<String> messages = new ArrayList<>();
        json(r).get("problems").forEach(p -> messages.add(p.get("message").asText()));
        assertThat(messages).containsExactlyInAnyOrder(
                "Frame 'Scout' has priority \"high\", which is not an integer (from -2147483648 to 2147483647).",
                "Slot 'sonars' of frame 'Scout' has required \"maybe\", which is not true or false.");
        assertThat(huge.statusCode()).as(huge.body()).isEqualTo(422);
        assertThat(kb.contains("Scout")).isFalse();
    }

    @Test void create_withAListValueThatIsAnObject_answers422InsteadOfSavingAnEmptyList() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.post("/api/frames", """
                {"name":"Scout","kind":"CLASS","parent":"Robot",
                 "slots":[{"name":"abilities","type":"TYPE_LIST","value":{"items":["drive"]}},
                          {"name":"poses","type":"TYPE_LIST","value":["sit",["lie"]]}]}""");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(422);
        List<String> messages = new ArrayList<>();
        json(r).get("problems").forEach(p -> messages.add(p.get("message").asText()));
        assertThat(messages).containsExactlyInAnyOrder(
                "Slot 'abilities' of frame 'Scout' value is not valid: {\"items\":[\"drive\"]} is not a list: write an "
                        + "array of texts or comma-separated text.",
                "Slot 'poses' of frame 'Scout' value is not valid: the item [\"lie\"] is not a text; lists inside lists "
                        + "are not supported.");
        assertThat(kb.contains("Scout")).isFalse();
    }

    @Test void create_withFacetsWrittenAsTheXmlWritesThem_keepsThem() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.post("/api/frames", """
                {"name":"Scout","kind":"CLASS","parent":"Robot","priority":"3",
                 "slots":[{"name":"sonars","type":"TYPE_INT","required":"TRUE","shared":"FALSE"}]}""");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(201);
        assertThat(kb.require("Scout").priority()).isEqualTo(3);
        assertThat(kb.require("Scout").ownSlot("sonars")).hasValueSatisfying(slot -> {
            assertThat(slot.required()).isTrue();
            assertThat(slot.shared()).isFalse();
        });
    }

    @Test void create_withASlotSentWithoutAType_takesTheTypeItsClassDeclares() {
        http.login(PASSWORD);
        HttpResponse<String> cls = http.post("/api/frames", """
                {"name":"Counter","kind":"CLASS","slots":[{"name":"count","type":"TYPE_INT"}]}""");

        HttpResponse<String> r = http.post("/api/frames", """
                {"name":"c1","kind":"INSTANCE","parent":"Counter","slots":[{"name":"count","value":"3"},
                 {"name":"note","value":"new"}]}""");

        assertThat(cls.statusCode()).as(cls.body()).isEqualTo(201);
        assertThat(r.statusCode()).as(r.body()).isEqualTo(201);
        assertThat(kb.value("c1", "count")).contains(Value.of(3));
        assertThat(kb.require("c1").ownSlot("note").map(Slot::type)).as("declared nowhere above: a string")
                .contains(DataType.STRING);
    }

    @Test void create_withAListSentWithoutAnArgument_readsItsItemsAsTheClassDeclares() {
        kb.add(Frame.classFrame("Sighting").slot(Slot.builder("face", DataType.LIST).argument("TYPE_FLOAT").build())
                .build());
        http.login(PASSWORD);

        HttpResponse<String> r = http.post("/api/frames", """
                {"name":"seen1","kind":"INSTANCE","parent":"Sighting","slots":[{"name":"face","value":["0.5","2"]}]}""");
        HttpResponse<String> bad = http.post("/api/frames", """
                {"name":"seen2","kind":"INSTANCE","parent":"Sighting","slots":[{"name":"face","value":["wide"]}]}""");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(201);
        assertThat(kb.value("seen1", "face")).contains(new Value.Lst(List.of(Value.of(0.5), Value.of(2.0))));
        assertThat(bad.statusCode()).as(bad.body()).isEqualTo(422);
        assertThat(json(bad).get("problems").get(0).get("slot").asText()).isEqualTo("face");
        assertThat(kb.contains("seen2")).isFalse();
    }

    @Test void create_withIsACycle_answers422() {
        http.login(PASSWORD);
        ObjectNode system = (ObjectNode) json(http.get("/api/frames/System"));
        system.put("parent", "Robot").put("expectedRevision", system.get("revision").asLong());

        HttpResponse<String> r = http.put("/api/frames/System", system.toString());

        assertThat(r.statusCode()).isEqualTo(422);
        assertThat(json(r).get("error").asText()).contains("System");
        assertThat(kb.require("System").parent()).isEmpty();
    }

    @Test void delete_ofFrameWithSubFrames_answers422AndKeepsIt() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.delete("/api/frames/User");

        assertThat(r.statusCode()).isEqualTo(422);
        assertThat(json(r).get("error").asText()).contains("'User' cannot be removed");
        assertThat(kb.contains("User")).isTrue();
    }

    @Test void rename_movesTheFrameAndRewritesReferences() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.post("/api/frames/NewUser/rename", "{\"newName\":\"Visitor\"}");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        assertThat(kb.contains("NewUser")).isFalse();
        assertThat(kb.require("Visitor").parent()).contains("User");
        assertThat(kb.require("AskUserName").ownSlot("mUser").flatMap(s -> s.argument())).contains("Visitor");
    }

    @Test void rename_ofClassWithSubFrames_rewritesTheirParent() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.post("/api/frames/Robot/rename", "{\"newName\":\"Machine\"}");

        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        assertThat(kb.require("HumanoidRobot").parent()).contains("Machine");
        assertThat(kb.value("Robovie", "battery")).contains(Value.of(100));
    }

    @Test void rename_toExistingName_answers422AndChangesNothing() {
        http.login(PASSWORD);
        long version = kb.version();

        HttpResponse<String> r = http.post("/api/frames/NewUser/rename", "{\"newName\":\"KnownUser\"}");

        assertThat(r.statusCode()).isEqualTo(422);
        assertThat(kb.version()).isEqualTo(version);
    }

    @Test void writes_withoutLogin_answer401WhileReadsWork() {
        assertThat(http.get("/api/frames/Robot").statusCode()).isEqualTo(200);

        HttpResponse<String> r = http.post("/api/frames", "{\"name\":\"Intruder\",\"parent\":\"System\"}");

        assertThat(r.statusCode()).isEqualTo(401);
        assertThat(json(r).get("error").asText()).isEqualTo("Log in to edit: the editor is read-only without a login.");
        assertThat(kb.contains("Intruder")).isFalse();
        assertThat(http.delete("/api/frames/Taro").statusCode()).isEqualTo(401);
    }

    @Test void login_withWrongPassword_isRefusedWithMessageAndGrantsNothing() {
        HttpResponse<String> r = http.login("guess");

        assertThat(r.statusCode()).isEqualTo(401);
        assertThat(json(r).get("error").asText()).isEqualTo("Wrong password: you were not logged in.");
        assertThat(r.headers().firstValue("Set-Cookie")).isEmpty();
        assertThat(http.delete("/api/frames/Taro").statusCode()).isEqualTo(401);
    }

    @Test void login_afterRepeatedWrongPasswords_isRefusedForAWhileEvenWithTheRightOne() {
        for (int i = 0; i < LoginThrottle.MAX_FAILURES; i++) {
            assertThat(http.login("guess " + i).statusCode()).isEqualTo(401);
        }

        HttpResponse<String> r = http.login(PASSWORD);

        assertThat(r.statusCode()).isEqualTo(429);
        assertThat(json(r).get("error").asText()).startsWith("Too many wrong passwords from this address");
        assertThat(r.headers().firstValue("Set-Cookie")).isEmpty();
    }

    @Test void login_withManyWrongPasswordsSentAtOnce_letsOnlyMaxFailuresOfThemBeTried() throws Exception {
        // Every guess's headers arrive before any body does, as a guesser's parallel requests may: the server
        // checks the throttle, then waits for the password.
        int guesses = 40;
        List<java.net.Socket> sockets = new ArrayList<>();
        try {
            for (int i = 0; i < guesses; i++) {
                sockets.add(new java.net.Socket("127.0.0.1", server.port()));
            }
            List<String> bodies = new ArrayList<>();
            for (int i = 0; i < guesses; i++) {
                bodies.add("{\"password\":\"guess " + i + "\"}");
                sockets.get(i).getOutputStream().write(("POST /api/login HTTP/1.1\r\nHost: 127.0.0.1:" + server.port()
                        + "\r\nContent-Type: application/json\r\nContent-Length: " + bodies.get(i).length()
                        + "\r\nConnection: close\r\n\r\n").getBytes(java.nio.charset.StandardCharsets.UTF_8));
            }
            Thread.sleep(300);
            for (int i = 0; i < guesses; i++) {
                sockets.get(i).getOutputStream().write(bodies.get(i).getBytes(java.nio.charset.StandardCharsets.UTF_8));
            }
            List<Integer> statuses = new ArrayList<>();
            for (java.net.Socket socket : sockets) {
                socket.setSoTimeout(30_000);
                String statusLine = new java.io.BufferedReader(new java.io.InputStreamReader(socket.getInputStream(),
                        java.nio.charset.StandardCharsets.UTF_8)).readLine();
                statuses.add(Integer.parseInt(statusLine.split(" ")[1]));
            }

            assertThat(statuses).filteredOn(s -> s == 401).as("guesses compared with the password")
                    .hasSize(LoginThrottle.MAX_FAILURES);
            assertThat(statuses).filteredOn(s -> s == 429).hasSize(guesses - LoginThrottle.MAX_FAILURES);
        } finally {
            for (java.net.Socket socket : sockets) {
                socket.close();
            }
        }
    }

    @Test void login_setsHttpOnlyStrictCookie_andLogoutEndsTheSession() {
        HttpResponse<String> r = http.login(PASSWORD);

        assertThat(r.statusCode()).isEqualTo(200);
        assertThat(r.headers().firstValue("Set-Cookie")).hasValueSatisfying(c -> assertThat(c)
                .contains("HttpOnly").containsIgnoringCase("SameSite=Strict"));
        assertThat(json(http.get("/api/session")).get("loggedIn").asBoolean()).isTrue();
        String session = r.headers().firstValue("Set-Cookie").orElseThrow().split(";", 2)[0];

        http.post("/api/logout", "{}");

        HttpResponse<String> after = http.send(http.jsonRequest("/api/frames/Taro").header("Cookie", session).DELETE());
        assertThat(after.statusCode()).isEqualTo(401);
    }

    @Test void delete_withoutBodyOrContentType_worksWhenLoggedIn() {
        http.login(PASSWORD);

        HttpResponse<String> r = http.send(java.net.http.HttpRequest.newBuilder(
                java.net.URI.create("http://127.0.0.1:" + server.port() + "/api/frames/Taro")).DELETE());

        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        assertThat(kb.contains("Taro")).isFalse();
    }

    @Test void bearerToken_allowsEditingWithoutCookie() {
        HttpResponse<String> r = http.send(http.jsonRequest("/api/frames/Taro")
                .header("Authorization", "Bearer " + PASSWORD).DELETE());

        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        assertThat(kb.contains("Taro")).isFalse();
    }

    @Test void bearerToken_withWrongPasswords_isRefusedInWordsAndThrottledLikeALogin() {
        HttpResponse<String> first = null;
        for (int i = 0; i < LoginThrottle.MAX_FAILURES; i++) {
            HttpResponse<String> r = http.send(http.jsonRequest("/api/frames/Taro")
                    .header("Authorization", "Bearer guess " + i).DELETE());
            first = first == null ? r : first;
        }

        HttpResponse<String> right = http.send(http.jsonRequest("/api/frames/Taro")
                .header("Authorization", "Bearer " + PASSWORD).DELETE());

        assertThat(first.statusCode()).isEqualTo(401);
        assertThat(json(first).get("error").asText())
                .isEqualTo("Wrong password in the Authorization header: you were not logged in.");
        assertThat(right.statusCode()).as(right.body()).isEqualTo(429);
        assertThat(json(right).get("error").asText()).startsWith("Too many wrong passwords from this address");
        assertThat(kb.contains("Taro")).isTrue();
    }

    @Test void writes_notJsonOrFromAnotherOrigin_areRefused() {
        http.login(PASSWORD);

        HttpResponse<String> form = http.send(http.jsonRequest("/api/frames").setHeader("Content-Type", "text/plain")
                .POST(java.net.http.HttpRequest.BodyPublishers.ofString("{\"name\":\"X\"}")));
        HttpResponse<String> foreign = http.send(http.jsonRequest("/api/frames").header("Origin", "http://evil.example")
                .POST(java.net.http.HttpRequest.BodyPublishers.ofString("{\"name\":\"X\",\"parent\":\"System\"}")));

        assertThat(form.statusCode()).isEqualTo(415);
        assertThat(foreign.statusCode()).isEqualTo(403);
        assertThat(kb.contains("X")).isFalse();
        // refused unread, so the server says it closes the connection: no request follows on it and gets nothing
        assertThat(form.headers().firstValue("Connection")).contains("close");
        assertThat(foreign.headers().firstValue("Connection")).contains("close");
    }

    @Test void request_namingAForeignHost_isRefused_againstDnsRebinding() throws Exception {
        try (java.net.Socket socket = new java.net.Socket("127.0.0.1", server.port())) {
            socket.getOutputStream().write(("GET /api/frames HTTP/1.1\r\nHost: evil.example:" + server.port()
                    + "\r\nConnection: close\r\n\r\n").getBytes(java.nio.charset.StandardCharsets.US_ASCII));
            String answer = new String(socket.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);

            assertThat(answer).startsWith("HTTP/1.1 421").doesNotContain("AskUserName");
        }
        assertThat(http.send(java.net.http.HttpRequest.newBuilder(java.net.URI.create(
                "http://localhost:" + server.port() + "/api/frames"))).statusCode()).isEqualTo(200);
    }

    @Test void readOnlyEditor_withoutPassword_refusesLogin() {
        try (EditorServer readOnly = EditorServer.start(EditorConfig.defaults().withPort(0), kb)) {
            Http other = new Http(readOnly.port());

            HttpResponse<String> r = other.login("anything");

            assertThat(r.statusCode()).isEqualTo(401);
            assertThat(json(r).get("error").asText()).contains("no editor password is configured");
            assertThat(json(other.get("/api/session")).get("editingPossible").asBoolean()).isFalse();
        }
    }

    @Test void page_isServedWithContentSecurityPolicy() {
        HttpResponse<String> r = http.get("/");

        assertThat(r.statusCode()).isEqualTo(200);
        assertThat(r.body()).contains("<title>K-ICNP knowledge editor</title>");
        assertThat(r.headers().firstValue("Content-Security-Policy")).hasValueSatisfying(c ->
                assertThat(c).contains("default-src 'none'").contains("connect-src 'self'"));
        assertThat(http.get("/../pom.xml").statusCode()).isNotEqualTo(200);
    }

    static JsonNode find(JsonNode array, String name) {
        for (JsonNode n : array) {
            JsonNode nameNode = n.has("slot") ? n.get("slot").get("name") : n.get("name");
            if (nameNode.asText().equals(name)) {
                return n;
            }
        }
        throw new AssertionError("No '" + name + "' in " + array);
    }

    /** The frame as the page gets it, with the revision it was read at as the expected one: ready to change and PUT. */
    private ObjectNode forEditing(String frame) {
        ObjectNode f = (ObjectNode) json(http.get("/api/frames/" + frame));
        f.put("expectedRevision", f.get("revision").asLong());
        return f;
    }
}
