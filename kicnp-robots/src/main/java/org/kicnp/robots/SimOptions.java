package org.kicnp.robots;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Objects;
import java.util.Optional;

/**
 * How to start the simulator: the seed (faces and sensor noise), the real-time speed-up, manual stepping, where the
 * repository is (absent: found by walking up from the working directory), and how long a request may wait for its
 * ack before it fails.
 */
public record SimOptions(long seed, double timeScale, boolean manual, Optional<Path> repoRoot, Duration requestTimeout) {
    public SimOptions {
        if (!(timeScale >= 0 && timeScale <= 1000)) {
            throw new IllegalArgumentException("Time scale " + timeScale + " is outside 0..1000.");
        }
        Objects.requireNonNull(repoRoot, "repoRoot");
        Objects.requireNonNull(requestTimeout, "requestTimeout");
        if (requestTimeout.isZero() || requestTimeout.isNegative()) {
            throw new IllegalArgumentException("The request timeout must be positive, not " + requestTimeout.toMillis()
                    + " ms.");
        }
    }

    /** Seed 42, ten times real time, repository found from the working directory, 10 s per request. */
    public static SimOptions defaults() {
        return new SimOptions(42, 10, false, Optional.empty(), Duration.ofSeconds(10));
    }

    public SimOptions withSeed(long s) {
        return new SimOptions(s, timeScale, manual, repoRoot, requestTimeout);
    }

    public SimOptions withTimeScale(double x) {
        return new SimOptions(seed, x, manual, repoRoot, requestTimeout);
    }

    /** Manual mode: the world moves only on {@link SimWorld#step} calls (deterministic; used by tests). */
    public SimOptions withManual(boolean on) {
        return new SimOptions(seed, timeScale, on, repoRoot, requestTimeout);
    }

    public SimOptions withRepoRoot(Path root) {
        return new SimOptions(seed, timeScale, manual, Optional.of(root), requestTimeout);
    }

    public SimOptions withRequestTimeout(Duration d) {
        return new SimOptions(seed, timeScale, manual, repoRoot, d);
    }
}
