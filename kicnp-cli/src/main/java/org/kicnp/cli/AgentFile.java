package org.kicnp.cli;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Properties;

/** The agent file {@code serve} writes ({@code NAME.token}, {@code NAME.kinds}), read by the verbs that connect. */
final class AgentFile {
    private AgentFile() {
    }

    /**
     * The file's entries.
     *
     * @throws IllegalArgumentException saying, for a person, that the file is missing (and where serve writes it) or
     *     why it cannot be read
     */
    static Properties read(Path file) {
        Properties entries = new Properties();
        try (InputStream in = Files.newInputStream(file)) {
            entries.load(in);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException("There is no agent file '" + file + "'; give --tokens "
                    + "KB_DIR/.kicnp/agents.properties of the running server (serve writes it there).");
        } catch (IOException | IllegalArgumentException e) {
            throw new IllegalArgumentException("Cannot read the agent file '" + file + "': " + e.getMessage());
        }
        return entries;
    }
}
