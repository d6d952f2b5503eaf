package org.kicnp.editor;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.security.SecureRandom;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.Base64;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Who may edit: checks the configured password (or token) in constant time and hands out random session tokens
 * that expire. The password itself never leaves this class; without a configured password nobody can log in and
 * the editor stays read-only.
 */
final class Sessions {
    private final Optional<byte[]> secretDigest;
    private final Duration lifetime;
    private final Clock clock;
    private final SecureRandom random = new SecureRandom();
    private final Map<String, Instant> sessions = new ConcurrentHashMap<>();

    Sessions(Optional<String> secret, Duration lifetime, Clock clock) {
        this.secretDigest = secret.map(Sessions::digest);
        this.lifetime = lifetime;
        this.clock = clock;
    }

    /** Whether a password is configured at all. */
    boolean editingPossible() {
        return secretDigest.isPresent();
    }

    /** Whether the given password is the configured one; compares digests in constant time. */
    boolean matches(String candidate) {
        return secretDigest.map(d -> MessageDigest.isEqual(d, digest(candidate))).orElse(false);
    }

    /** Opens a session for a correct password: the token to put in the session cookie. */
    String open() {
        byte[] bytes = new byte[32];
        random.nextBytes(bytes);
        String token = Base64.getUrlEncoder().withoutPadding().encodeToString(bytes);
        sessions.put(token, clock.instant().plus(lifetime));
        return token;
    }

    /** Whether the token names a live session; expired sessions are dropped. */
    boolean valid(String token) {
        Instant until = sessions.get(token);
        if (until == null) {
            return false;
        }
        if (clock.instant().isAfter(until)) {
            sessions.remove(token);
            return false;
        }
        return true;
    }

    void close(String token) {
        sessions.remove(token);
    }

    Duration lifetime() {
        return lifetime;
    }

    private static byte[] digest(String s) {
        try {
            return MessageDigest.getInstance("SHA-256").digest(s.getBytes(StandardCharsets.UTF_8));
        } catch (NoSuchAlgorithmException e) {
            throw new EditorException("The JDK has no SHA-256, which the editor's login needs.", e);
        }
    }
}
