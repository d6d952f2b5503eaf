package org.kicnp.cli.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import org.junit.jupiter.api.Test;

/** The scenario's copy of the parser's case-frame classes stays the same as the parser's own. */
class ScenarioFilesTest {
    @Test
    void languageXml_inTheScenario_equalsTheParsersClassFrames() throws Exception {
        String scenario = Files.readString(ScenarioFiles.table5().resolve("language.xml"), StandardCharsets.UTF_8);
        try (InputStream in = getClass().getResourceAsStream("/org/kicnp/language/language.xml")) {
            assertThat(in).as("kicnp-language's language.xml on the class path").isNotNull();
            assertThat(scenario).isEqualTo(new String(in.readAllBytes(), StandardCharsets.UTF_8));
        }
    }
}
