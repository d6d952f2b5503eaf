package org.kicnp.cli.platform;

import static java.nio.charset.StandardCharsets.UTF_8;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.List;
import java.util.Properties;

/**
 * The platform's generated secrets: a default agent file with a random token per agent, and the editor password.
 * Files are created owner-read/write only where the file system allows it.
 */
final class Secrets {
    /** The agents a default agent file lets in: the four robots, the sentence parser (a service) and user agents (User A's microphone, a user, a director). */
    static final List<String> ROBOTS = List.of("robovie", "pino", "scout", "aibo");
    static final List<String> USERS = List.of("userA", "user", "director");

    private static final SecureRandom RANDOM = new SecureRandom();

    private Secrets() {
    }

    static String token() {
        byte[] b = new byte[16];
        RANDOM.nextBytes(b);
        return HexFormat.of().formatHex(b);
    }

    /** Writes a default agent file unless it exists; returns whether it was written. */
    static boolean writeAgentsFile(Path file) {
        if (Files.exists(file)) {
            return false;
        }
        Properties p = new Properties();
        for (String robot : ROBOTS) {
            p.setProperty(robot + ".token", token());
            p.setProperty(robot + ".kinds", "robot");
        }
        p.setProperty("parser.token", token());
        p.setProperty("parser.kinds", "service");
        for (String user : USERS) {
            p.setProperty(user + ".token", token());
            p.setProperty(user + ".kinds", "user");
        }
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            try (Writer w = Files.newBufferedWriter(create(file), UTF_8)) {
                p.store(w, "K-ICNP agent tokens, generated on first start");
            }
            return true;
        } catch (IOException e) {
            throw new UncheckedIOException("Cannot write the agent file '" + file + "': " + e.getMessage(), e);
        }
    }

    /** Reads the password in a file (first line, trimmed), generating a random one when the file is missing. */
    static String password(Path file) {
        try {
            if (!Files.exists(file)) {
                Files.createDirectories(file.toAbsolutePath().getParent());
                Files.writeString(create(file), token() + "\n", UTF_8);
            }
            String text = Files.readString(file, UTF_8).strip();
            if (text.isEmpty()) {
                throw new IllegalArgumentException("The editor password file '" + file + "' is empty.");
            }
            return text.lines().findFirst().orElseThrow().strip();
        } catch (IOException e) {
            throw new UncheckedIOException("Cannot read the editor password file '" + file + "': " + e.getMessage(), e);
        }
    }

    private static Path create(Path file) throws IOException {
        try {
            return Files.createFile(file, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
        } catch (UnsupportedOperationException e) {
            return Files.createFile(file);
        }
    }
}
