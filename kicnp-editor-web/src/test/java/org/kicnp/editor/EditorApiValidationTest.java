package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.net.http.HttpResponse;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * The JSON API's checks of the frames sent to it, against a real Jetty on an ephemeral loopback port: values of the
 * wrong type, scripts that do not parse, unknown classes and facets that are not what they should be answered 422
 * with every problem and its frame and slot, changing nothing; facets written as the XML writes them, and slots sent
 * without a type or list argument, read as their class declares them.
 */
class EditorApiValidationTest extends EditorApiFixture {
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

    /** The frame as the page gets it, with the revision it was read at as the expected one: ready to change and PUT. */
    private ObjectNode forEditing(String frame) {
        ObjectNode f = (ObjectNode) json(http.get("/api/frames/" + frame));
        f.put("expectedRevision", f.get("revision").asLong());
        return f;
    }
}
