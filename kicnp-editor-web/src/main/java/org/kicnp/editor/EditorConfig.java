package org.kicnp.editor;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.Properties;

/**
 * How the editor listens and who may edit. Defaults: {@code 127.0.0.1:8080}, no password (read-only), sessions
 * of eight hours. Port 0 picks a free port (tests). Read from a properties file with {@link #load(Path)}:
 * {@code editor.host}, {@code editor.port}, {@code editor.password}, {@code editor.sessionHours}.
 *
 * @param host the address to bind; loopback unless deliberately opened up
 * @param port the TCP port, 0 for any free one
 * @param password the password (or token) that unlocks editing; empty keeps the editor read-only
 * @param sessionLifetime how long a login lasts
 */
public record EditorConfig(String host, int port, Optional<String> password, Duration sessionLifetime) {
    public static final String DEFAULT_HOST = "127.0.0.1";
    public static final int DEFAULT_PORT = 8080;

    public EditorConfig {
        requireNonNull(host, "host");
        requireNonNull(password, "password");
        requireNonNull(sessionLifetime, "sessionLifetime");
        if (port < 0 || port > 65535) {
            throw new EditorException("Editor port " + port + " is not a TCP port (0 to 65535).");
        }
        if (password.isPresent() && password.get().isBlank()) {
            throw new EditorException("The editor password must not be blank; leave it out for a read-only editor.");
        }
    }

    /** Loopback, port 8080, read-only. */
    public static EditorConfig defaults() {
        return new EditorConfig(DEFAULT_HOST, DEFAULT_PORT, Optional.empty(), Duration.ofHours(8));
    }

    public EditorConfig withHost(String h) {
        return new EditorConfig(h, port, password, sessionLifetime);
    }

    public EditorConfig withPort(int p) {
        return new EditorConfig(host, p, password, sessionLifetime);
    }

    public EditorConfig withPassword(String secret) {
        return new EditorConfig(host, port, Optional.of(requireNonNull(secret, "secret")), sessionLifetime);
    }

    /** Reads the settings from a properties file; missing keys keep their defaults. */
    public static EditorConfig load(Path file) {
        Properties p = new Properties();
        try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            p.load(r);
        } catch (IOException e) {
            throw new EditorException("Cannot read the editor settings file '" + file + "': " + e.getMessage(), e);
        }
        return from(p, file.toString());
    }

    /** Reads the settings from properties; {@code source} names them in error messages. */
    public static EditorConfig from(Properties p, String source) {
        EditorConfig c = defaults().withHost(p.getProperty("editor.host", DEFAULT_HOST).strip());
        String port = p.getProperty("editor.port");
        if (port != null) {
            try {
                c = c.withPort(Integer.parseInt(port.strip()));
            } catch (NumberFormatException e) {
                throw new EditorException("editor.port '" + port + "' in " + source + " is not a number.");
            }
        }
        String password = p.getProperty("editor.password");
        if (password != null && !password.isBlank()) {
            c = c.withPassword(password.strip());
        }
        String hours = p.getProperty("editor.sessionHours");
        if (hours != null) {
            try {
                c = new EditorConfig(c.host, c.port, c.password, Duration.ofHours(Long.parseLong(hours.strip())));
            } catch (NumberFormatException e) {
                throw new EditorException("editor.sessionHours '" + hours + "' in " + source + " is not a number.");
            }
        }
        return c;
    }

    @Override public String toString() {
        return "EditorConfig[" + host + ":" + port + (password.isPresent() ? ", password set" : ", read-only") + "]";
    }
}
