package org.kicnp.cli.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Finding the scenario, and its copy of the parser's case-frame classes staying the same as the parser's own. */
class ScenarioFilesTest {
    @Test
    void languageXml_inTheScenario_equalsTheParsersClassFrames() throws Exception {
        String scenario = Files.readString(ScenarioFiles.table5().resolve("language.xml"), StandardCharsets.UTF_8);
        try (InputStream in = getClass().getResourceAsStream("/org/kicnp/language/language.xml")) {
            assertThat(in).as("kicnp-language's language.xml on the class path").isNotNull();
            assertThat(scenario).isEqualTo(new String(in.readAllBytes(), StandardCharsets.UTF_8));
        }
    }

    @Test
    void repoRoot_fromOutsideTheRepository_usesTheRepositoryTheLauncherNames(@TempDir Path elsewhere) {
        Path repo = ScenarioFiles.table5().getParent().getParent();

        assertThat(ScenarioFiles.repoRoot(Optional.of(repo.toString()), elsewhere)).contains(repo);
        assertThat(ScenarioFiles.repoRoot(Optional.empty(), elsewhere)).isEmpty();
        assertThat(ScenarioFiles.repoRoot(Optional.of(elsewhere.toString()), repo.resolve("docs"))).contains(repo);
    }
}
