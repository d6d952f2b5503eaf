package org.kicnp.inference;

import java.time.Duration;

/**
 * Settings of one engine: the hard limit of firings per run to quiescence, the default action timeout, and the
 * bounds of backward chaining (depth, number of answers, and combinations of instances tried per question), which
 * keep a question from exploding.
 */
public record EngineOptions(int maxFirings, Duration actionTimeout, int maxProofDepth, int maxAnswers,
                            int maxQuestionSteps) {
    public EngineOptions {
        if (maxFirings < 1 || maxProofDepth < 1 || maxAnswers < 1 || maxQuestionSteps < 1) {
            throw new IllegalArgumentException("Engine limits must be positive.");
        }
        if (actionTimeout.isNegative() || actionTimeout.isZero()) {
            throw new IllegalArgumentException("The action timeout must be positive.");
        }
    }

    /** The default number of combinations a question may try ({@link #maxQuestionSteps}). */
    public static final int QUESTION_STEPS = 1_000_000;

    /** With the default {@link #maxQuestionSteps}. */
    public EngineOptions(int maxFirings, Duration actionTimeout, int maxProofDepth, int maxAnswers) {
        this(maxFirings, actionTimeout, maxProofDepth, maxAnswers, QUESTION_STEPS);
    }

    /**
     * 10,000 firings, 30 s per action, proofs 8 deep, 1,000 answers, 1,000,000 combinations per question (about a
     * second and a half here: {@code ask} over two slots of 1,000 instances each took 1.57 s).
     */
    public static EngineOptions defaults() {
        return new EngineOptions(10_000, Duration.ofSeconds(30), 8, 1_000, QUESTION_STEPS);
    }

    public EngineOptions withMaxFirings(int n) {
        return new EngineOptions(n, actionTimeout, maxProofDepth, maxAnswers, maxQuestionSteps);
    }

    public EngineOptions withActionTimeout(Duration d) {
        return new EngineOptions(maxFirings, d, maxProofDepth, maxAnswers, maxQuestionSteps);
    }

    public EngineOptions withMaxAnswers(int n) {
        return new EngineOptions(maxFirings, actionTimeout, maxProofDepth, n, maxQuestionSteps);
    }

    public EngineOptions withMaxQuestionSteps(int n) {
        return new EngineOptions(maxFirings, actionTimeout, maxProofDepth, maxAnswers, n);
    }
}
