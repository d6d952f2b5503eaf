package org.kicnp.gateway;

import static java.nio.charset.StandardCharsets.UTF_8;
import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.Set;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message.Hello;

/**
 * Who may connect: a token per agent and the kinds it may connect as, read from {@code agents.properties}
 * ({@code NAME.token = secret}, {@code NAME.kinds = robot,user}; kinds default to any). A hello costs the same
 * whether its name is known or not and whatever its token's length: the SHA-256 of the token it sends is compared
 * in constant time with the agent's (or, for an unknown name, with a dummy's), so neither the answer nor its timing
 * tells a stranger which names exist. Immutable.
 */
public final class AgentDirectory {
    /** An agent's token, kept as its SHA-256, and its kinds. */
    private record Entry(byte[] tokenDigest, Set<AgentKind> kinds) {
    }

    /** What the token of a hello under an unknown name is compared with: the same work as for a known name. */
    private static final byte[] DUMMY_DIGEST = sha256("no agent has this token");

    private final Map<String, Entry> entries;

    private AgentDirectory(Map<String, Entry> entries) {
        this.entries = Map.copyOf(entries);
    }

    /** Reads an agent file. */
    public static AgentDirectory load(Path file) {
        try (Reader r = Files.newBufferedReader(file, UTF_8)) {
            Properties p = new Properties();
            p.load(r);
            return of(p, file.toString());
        } catch (IOException e) {
            throw new GatewayException("Cannot read the agent file '" + file + "': " + e.getMessage(), e);
        }
    }

    /**
     * Builds a directory from agent-file properties.
     *
     * @throws GatewayException when a key is not {@code NAME.token} or {@code NAME.kinds}, a kind is unknown, a
     *     token is empty, or an agent has kinds but no token
     */
    public static AgentDirectory of(Properties p, String source) {
        Map<String, byte[]> tokens = new HashMap<>();
        Map<String, Set<AgentKind>> kinds = new HashMap<>();
        for (String key : p.stringPropertyNames()) {
            String value = p.getProperty(key).strip();
            int dot = key.lastIndexOf('.');
            String name = dot < 0 ? "" : key.substring(0, dot);
            switch (dot < 0 ? "" : key.substring(dot + 1)) {
                case "token" -> {
                    if (value.isEmpty()) { // it would match the empty token: anyone could connect under this name
                        throw new GatewayException("Agent '" + name + "' in '" + source
                                + "' has an empty token; give it a secret, or remove it.");
                    }
                    tokens.put(name, sha256(value));
                }
                case "kinds" -> kinds.put(name, parseKinds(value, key, source));
                default -> throw new GatewayException("Key '" + key + "' in the agent file '" + source
                        + "' is neither NAME.token nor NAME.kinds.");
            }
        }
        Map<String, Entry> entries = new HashMap<>();
        for (String name : kinds.keySet()) {
            if (!tokens.containsKey(name)) {
                throw new GatewayException("Agent '" + name + "' in '" + source + "' has kinds but no token.");
            }
        }
        tokens.forEach((name, token) -> entries.put(name,
                new Entry(token, kinds.getOrDefault(name, EnumSet.allOf(AgentKind.class)))));
        return new AgentDirectory(entries);
    }

    /** Starts a directory in code (tests, embedding). */
    public static AgentDirectory empty() {
        return new AgentDirectory(Map.of());
    }

    /** A copy that also admits {@code name} with {@code token} as any of {@code kinds}. */
    public AgentDirectory with(String name, String token, AgentKind... kinds) {
        if (token.isEmpty()) {
            throw new GatewayException("Agent '" + name + "' has an empty token; give it a secret.");
        }
        Map<String, Entry> copy = new HashMap<>(entries);
        Set<AgentKind> allowed = kinds.length == 0 ? EnumSet.allOf(AgentKind.class) : EnumSet.of(kinds[0], kinds);
        copy.put(requireNonNull(name, "name"), new Entry(sha256(token), allowed));
        return new AgentDirectory(copy);
    }

    /** Why this hello is refused, or empty when it is accepted. */
    public Optional<String> refusal(Hello hello) {
        Entry e = entries.get(hello.agent());
        boolean tokenMatches = MessageDigest.isEqual(e == null ? DUMMY_DIGEST : e.tokenDigest(), sha256(hello.token()));
        if (e == null || !tokenMatches) {
            // One answer for both, so a stranger cannot probe which agent names exist.
            return Optional.of("Unknown agent '" + hello.agent() + "' or wrong token.");
        }
        if (!e.kinds().contains(hello.kind())) {
            return Optional.of("Agent '" + hello.agent() + "' may not connect as a "
                    + hello.kind().name().toLowerCase(Locale.ROOT) + " agent.");
        }
        return Optional.empty();
    }

    private static byte[] sha256(String token) {
        try {
            return MessageDigest.getInstance("SHA-256").digest(token.getBytes(UTF_8));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("This JVM has no SHA-256, which every Java platform must have.", e);
        }
    }

    private static Set<AgentKind> parseKinds(String text, String key, String source) {
        Set<AgentKind> out = EnumSet.noneOf(AgentKind.class);
        for (String k : text.split(",")) {
            try {
                out.add(AgentKind.valueOf(k.strip().toUpperCase(Locale.ROOT)));
            } catch (IllegalArgumentException e) {
                throw new GatewayException("Unknown agent kind '" + k.strip() + "' for '" + key + "' in '" + source
                        + "'; use robot, user, service or peer.");
            }
        }
        return out;
    }
}
