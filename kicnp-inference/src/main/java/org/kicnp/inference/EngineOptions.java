package org.kicnp.inference;

import java.time.Duration;

/**
 * Settings of one engine: the hard limit of firings per run to quiescence, the default action timeout, and the
 * bounds of backward chaining (depth and number of answers), which keep a question from exploding.
 */
public record EngineOptions(int maxFirings, Duration actionTimeout, int maxProofDepth, int maxAnswers) {
    public EngineOptions {
        if (maxFirings < 1 || maxProofDepth < 1 || maxAnswers < 1) {
            throw new IllegalArgumentException("Engine limits must be positive.");
        }
        if (actionTimeout.isNegative() || actionTimeout.isZero()) {
            throw new IllegalArgumentException("The action timeout must be positive.");
        }
    }

    /** 10,000 firings, 30 s per action, proofs 8 deep, 1,000 answers. */
    public static EngineOptions defaults() {
        return new EngineOptions(10_000, Duration.ofSeconds(30), 8, 1_000);
    }

    public EngineOptions withMaxFirings(int n) {
        return new EngineOptions(n, actionTimeout, maxProofDepth, maxAnswers);
    }

    public EngineOptions withActionTimeout(Duration d) {
        return new EngineOptions(maxFirings, d, maxProofDepth, maxAnswers);
    }

    public EngineOptions withMaxAnswers(int n) {
        return new EngineOptions(maxFirings, actionTimeout, maxProofDepth, n);
    }
}
