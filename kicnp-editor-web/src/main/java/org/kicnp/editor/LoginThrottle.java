package org.kicnp.editor;

import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Slows password guessing: after {@link #MAX_FAILURES} wrong passwords from one address within {@link #WINDOW},
 * that address may not try again until the window has passed since its first failure. A correct password clears
 * the address's count. The map is bounded by pruning stale entries when it grows.
 */
final class LoginThrottle {
    static final int MAX_FAILURES = 5;
    static final Duration WINDOW = Duration.ofMinutes(5);
    private static final int PRUNE_AT = 10_000;

    private record Failures(Instant first, int count) {
    }

    private final Clock clock;
    private final Map<String, Failures> failures = new ConcurrentHashMap<>();

    LoginThrottle(Clock clock) {
        this.clock = clock;
    }

    /** Seconds the address must still wait before trying again, or 0 when it may try now. */
    long waitSeconds(String address) {
        Failures f = failures.get(address);
        if (f == null) {
            return 0;
        }
        Duration left = Duration.between(clock.instant(), f.first().plus(WINDOW));
        if (left.isNegative() || left.isZero()) {
            failures.remove(address);
            return 0;
        }
        return f.count() >= MAX_FAILURES ? Math.max(1, left.toSeconds()) : 0;
    }

    void failed(String address) {
        if (failures.size() > PRUNE_AT) {
            Instant now = clock.instant();
            failures.values().removeIf(f -> f.first().plus(WINDOW).isBefore(now));
        }
        failures.merge(address, new Failures(clock.instant(), 1), (old, one) -> new Failures(old.first(), old.count() + 1));
    }

    void succeeded(String address) {
        failures.remove(address);
    }
}
