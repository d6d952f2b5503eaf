package org.kicnp.protocol;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * The published schemas match the records. Run with {@code -Dkicnp.writeSchemas=true} to rewrite them after
 * changing a message.
 */
class SchemasTest {
    private static final Path DIR = Path.of("..", "docs", "protocol", "schemas");

    @Test
    void publishedSchemas_matchTheMessageRecords() throws Exception {
        boolean write = Boolean.getBoolean("kicnp.writeSchemas");
        for (MessageType type : MessageType.values()) {
            Path file = DIR.resolve(type.wireName() + ".json");
            String expected = new com.fasterxml.jackson.databind.ObjectMapper()
                    .enable(com.fasterxml.jackson.databind.SerializationFeature.INDENT_OUTPUT)
                    .writeValueAsString(SchemaGenerator.withDefinitions(SchemaGenerator.schema(type))) + "\n";
            if (write) {
                Files.createDirectories(DIR);
                Files.writeString(file, expected, StandardCharsets.UTF_8);
            }
            assertThat(file).as("schema of '%s' (rerun with -Dkicnp.writeSchemas=true)", type.wireName())
                    .content(StandardCharsets.UTF_8).isEqualTo(expected);
        }
    }

    /** The limits the schemas carry are the records': names, actions, ids, a relay's subject, class names; no others. */
    @Test
    void publishedSchemas_limitTheLengthOfTheMembersTheRecordsLimit() throws Exception {
        com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
        java.util.function.BiFunction<String, String, com.fasterxml.jackson.databind.JsonNode> member = (type, name) -> {
            try {
                return json.readTree(DIR.resolve(type + ".json").toFile()).path("properties").path(name);
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        };

        for (String[] limited : new String[][] {{"hello", "id"}, {"hello", "agent"}, {"relay", "from"},
                {"relay", "toAgent"}, {"relay", "subject"}, {"command", "robot"}, {"command", "action"},
                {"cancel", "command"}, {"feedback", "id"}, {"sensor", "sensor"}, {"query", "ofClass"},
                {"subscribe", "ofClass"}, {"unsubscribe", "ofClass"}, {"prove", "ofClass"}}) {
            assertThat(member.apply(limited[0], limited[1]).path("maxLength").asInt())
                    .as("%s's %s", limited[0], limited[1]).isEqualTo(Message.MAX_NAME_LENGTH);
        }
        for (String[] free : new String[][] {{"hello", "token"}, {"relay", "body"}, {"assert", "frame"},
                {"feedback", "detail"}, {"changed", "ofClass"}, {"ack", "id"}, {"error", "message"}}) {
            assertThat(member.apply(free[0], free[1]).has("maxLength")).as("%s's %s", free[0], free[1]).isFalse();
        }
        assertThat(member.apply("command", "args").path("additionalProperties").has("maxLength")).isFalse();
    }
}
