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
}
