package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class EditorConfigTest {
    @TempDir Path dir;

    @Test void defaults_bindLoopbackOnPort8080ReadOnly() {
        EditorConfig c = EditorConfig.defaults();

        assertThat(c.host()).isEqualTo("127.0.0.1");
        assertThat(c.port()).isEqualTo(8080);
        assertThat(c.password()).isEmpty();
    }

    @Test void load_readsEveryKeyFromAPropertiesFile() throws IOException {
        Path file = dir.resolve("kicnp.properties");
        Files.writeString(file, "editor.port=9090\neditor.password=s3cret\neditor.sessionHours=2\n");

        EditorConfig c = EditorConfig.load(file);

        assertThat(c.port()).isEqualTo(9090);
        assertThat(c.password()).contains("s3cret");
        assertThat(c.sessionLifetime()).isEqualTo(Duration.ofHours(2));
        assertThat(c.host()).isEqualTo("127.0.0.1");
        assertThat(c.toString()).doesNotContain("s3cret");
    }

    @Test void from_withBadPort_namesKeyValueAndSource() {
        Properties p = new Properties();
        p.setProperty("editor.port", "eighty");

        assertThatThrownBy(() -> EditorConfig.from(p, "kicnp.properties"))
                .isInstanceOf(EditorException.class)
                .hasMessage("editor.port 'eighty' in kicnp.properties is not a number.");
    }

    @Test void load_ofMissingFile_saysWhichFile() {
        Path missing = dir.resolve("nope.properties");

        assertThatThrownBy(() -> EditorConfig.load(missing)).isInstanceOf(EditorException.class)
                .hasMessageContaining("Cannot read the editor settings file '" + missing + "'");
    }

    @Test void start_onAPortInUse_failsWithSentence() {
        try (EditorServer first = EditorServer.start(EditorConfig.defaults().withPort(0),
                org.kicnp.core.KnowledgeBase.create())) {
            assertThatThrownBy(() -> EditorServer.start(EditorConfig.defaults().withPort(first.port()),
                    org.kicnp.core.KnowledgeBase.create()))
                    .isInstanceOf(EditorException.class)
                    .hasMessageStartingWith("The editor could not start on 127.0.0.1:" + first.port());
        }
    }
}
