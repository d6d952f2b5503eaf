package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.net.http.HttpResponse;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;
import org.kicnp.core.Relation;
import org.kicnp.core.Value;

/**
 * The JSON API against a real Jetty on an ephemeral loopback port: listing and reading frames, and creating, editing,
 * deleting and renaming them, with the changes refused (a missing or stale revision, an IS-A cycle, a class
 * with sub-frames, a name taken) answered in words and changing nothing.
 */
class EditorApiTest extends EditorApiFixture {
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

    static JsonNode find(JsonNode array, String name) {
        for (JsonNode n : array) {
            JsonNode nameNode = n.has("slot") ? n.get("slot").get("name") : n.get("name");
            if (nameNode.asText().equals(name)) {
                return n;
            }
        }
        throw new AssertionError("No '" + name + "' in " + array);
    }
}
