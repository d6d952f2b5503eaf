package org.kicnp.script;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.Properties;
import java.util.Set;
import java.util.stream.Collectors;

/**
 * The bounds and the Java allow-list every script runs under.
 *
 * @param timeLimit wall-clock time one run may take before it is stopped
 * @param statementLimit JavaScript statements one run may execute before it is stopped
 * @param allowedHostClasses fully qualified names of Java classes scripts may reach with {@code Java.type(name)};
 *     their public constructors, methods and fields (not those inherited from {@code Object}) become usable
 * @param maxIdleContexts how many idle contexts the runtime keeps for reuse; more are created under load
 *     and closed when returned
 */
public record ScriptConfig(Duration timeLimit, long statementLimit, Set<String> allowedHostClasses, int maxIdleContexts) {

    /** Property naming the wall-clock limit in milliseconds. */
    public static final String TIME_LIMIT_MS = "script.time.limit.ms";
    /** Property naming the statement limit. */
    public static final String STATEMENT_LIMIT = "script.statement.limit";
    /** Property listing allow-listed Java classes, comma separated. */
    public static final String ALLOW_CLASSES = "script.allow.classes";
    /** Property naming how many idle contexts are kept. */
    public static final String MAX_IDLE_CONTEXTS = "script.contexts.idle";

    private static final ScriptConfig DEFAULTS = new ScriptConfig(Duration.ofSeconds(1), 10_000_000L, Set.of(),
            Math.max(8, 2 * Runtime.getRuntime().availableProcessors()));

    public ScriptConfig {
        requireNonNull(timeLimit, "timeLimit");
        requireNonNull(allowedHostClasses, "allowedHostClasses");
        if (timeLimit.isNegative() || timeLimit.isZero()) {
            throw new IllegalArgumentException("The script time limit must be positive, not " + timeLimit + ".");
        }
        if (statementLimit <= 0) {
            throw new IllegalArgumentException("The script statement limit must be positive, not " + statementLimit + ".");
        }
        if (maxIdleContexts < 0) {
            throw new IllegalArgumentException("The number of idle script contexts cannot be negative: " + maxIdleContexts + ".");
        }
        allowedHostClasses = Set.copyOf(allowedHostClasses);
    }

    /**
     * 1 s, 10 million statements, no Java classes, twice as many idle contexts as processors (at least 8). The
     * time limit is generous because the first run of a code path is interpreted cold and can take a hundred
     * milliseconds or more on a busy machine; the statement limit stops tight loops well before it.
     */
    public static ScriptConfig defaults() {
        return DEFAULTS;
    }

    /**
     * Reads the configuration from properties, taking {@link #defaults()} for anything absent:
     * {@code script.time.limit.ms}, {@code script.statement.limit}, {@code script.allow.classes}
     * (for example {@code java.lang.Math,java.time.LocalDate}) and {@code script.contexts.idle}.
     */
    public static ScriptConfig fromProperties(Properties properties) {
        requireNonNull(properties, "properties");
        ScriptConfig d = defaults();
        Duration time = Duration.ofMillis(number(properties, TIME_LIMIT_MS, d.timeLimit().toMillis()));
        long statements = number(properties, STATEMENT_LIMIT, d.statementLimit());
        String classes = properties.getProperty(ALLOW_CLASSES, "");
        Set<String> allowed = Arrays.stream(classes.split(","))
                .map(String::strip)
                .filter(s -> !s.isEmpty())
                .collect(Collectors.toCollection(LinkedHashSet::new));
        int idle = Math.toIntExact(number(properties, MAX_IDLE_CONTEXTS, d.maxIdleContexts()));
        return new ScriptConfig(time, statements, allowed, idle);
    }

    public ScriptConfig withTimeLimit(Duration limit) {
        return new ScriptConfig(limit, statementLimit, allowedHostClasses, maxIdleContexts);
    }

    public ScriptConfig withStatementLimit(long limit) {
        return new ScriptConfig(timeLimit, limit, allowedHostClasses, maxIdleContexts);
    }

    public ScriptConfig withAllowedHostClasses(Set<String> classes) {
        return new ScriptConfig(timeLimit, statementLimit, classes, maxIdleContexts);
    }

    public ScriptConfig withMaxIdleContexts(int contexts) {
        return new ScriptConfig(timeLimit, statementLimit, allowedHostClasses, contexts);
    }

    private static long number(Properties properties, String key, long fallback) {
        String text = properties.getProperty(key);
        if (text == null || text.isBlank()) {
            return fallback;
        }
        try {
            return Long.parseLong(text.strip());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("The property '" + key + "' must be a whole number, not '" + text + "'.", e);
        }
    }
}
