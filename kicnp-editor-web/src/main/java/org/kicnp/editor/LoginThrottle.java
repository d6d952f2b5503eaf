package org.kicnp.editor;

import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Slows password guessing: after {@link #MAX_FAILURES} wrong passwords from one address within {@link #WINDOW},
 * that address may not try again until the window has passed since its first failure. A correct password clears
 * the address's count. Each guess is counted before it is compared ({@link #admit}), in one atomic step with the
 * check, so guesses sent in parallel cannot all pass the check before any of them is counted. The map is bounded
 * by pruning stale entries when it grows.
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

    /**
     * Lets one password guess from the address through, counting it as a failure until {@link #succeeded} clears
     * it, or refuses it: the seconds to wait, or 0 when the guess was admitted.
     */
    long admit(String address) {
        prune();
        long[] wait = {0};
        failures.compute(address, (a, f) -> {
            Instant now = clock.instant();
            if (f == null || !f.first().plus(WINDOW).isAfter(now)) {
                return new Failures(now, 1);
            }
            if (f.count() >= MAX_FAILURES) {
                wait[0] = Math.max(1, Duration.between(now, f.first().plus(WINDOW)).toSeconds());
                return f;
            }
            return new Failures(f.first(), f.count() + 1);
        });
        return wait[0];
    }

    private void prune() {
        if (failures.size() > PRUNE_AT) {
            Instant now = clock.instant();
            failures.values().removeIf(f -> f.first().plus(WINDOW).isBefore(now));
        }
    }

    void succeeded(String address) {
        failures.remove(address);
    }
}
