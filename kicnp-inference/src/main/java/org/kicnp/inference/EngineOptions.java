package org.kicnp.inference;

import java.time.Duration;

/**
 * Settings of one engine: the hard limits of firings per run to quiescence and of how deep derived instances may rest
 * on one another (both stop a runaway knowledge base), the default action timeout, and the
 * bounds of backward chaining (depth, number of answers, and combinations of instances tried per question), which
 * keep a question from exploding.
 */
public record EngineOptions(int maxFirings, Duration actionTimeout, int maxProofDepth, int maxAnswers,
                            int maxQuestionSteps, int maxDerivationDepth) {
    public EngineOptions {
        if (maxFirings < 1 || maxProofDepth < 1 || maxAnswers < 1 || maxQuestionSteps < 1 || maxDerivationDepth < 1) {
            throw new IllegalArgumentException("Engine limits must be positive.");
        }
        if (actionTimeout.isNegative() || actionTimeout.isZero()) {
            throw new IllegalArgumentException("The action timeout must be positive.");
        }
    }

    /** The default number of combinations a question may try ({@link #maxQuestionSteps}). */
    public static final int QUESTION_STEPS = 1_000_000;

    /** The default depth of derived instances resting on one another ({@link #maxDerivationDepth}). */
    public static final int DERIVATION_DEPTH = 10_000;

    /** With the default {@link #maxQuestionSteps} and {@link #maxDerivationDepth}. */
    public EngineOptions(int maxFirings, Duration actionTimeout, int maxProofDepth, int maxAnswers) {
        this(maxFirings, actionTimeout, maxProofDepth, maxAnswers, QUESTION_STEPS, DERIVATION_DEPTH);
    }

    /**
     * 10,000 firings in a row, 30 s per action, proofs 8 deep, 1,000 answers, 1,000,000 combinations per question
     * (about a second and a half here: {@code ask} over two slots of 1,000 instances each took 1.57 s), derived
     * instances 10,000 deep.
     */
    public static EngineOptions defaults() {
        return new EngineOptions(10_000, Duration.ofSeconds(30), 8, 1_000, QUESTION_STEPS, DERIVATION_DEPTH);
    }

    public EngineOptions withMaxFirings(int n) {
        return new EngineOptions(n, actionTimeout, maxProofDepth, maxAnswers, maxQuestionSteps, maxDerivationDepth);
    }

    public EngineOptions withActionTimeout(Duration d) {
        return new EngineOptions(maxFirings, d, maxProofDepth, maxAnswers, maxQuestionSteps, maxDerivationDepth);
    }

    public EngineOptions withMaxAnswers(int n) {
        return new EngineOptions(maxFirings, actionTimeout, maxProofDepth, n, maxQuestionSteps, maxDerivationDepth);
    }

    public EngineOptions withMaxQuestionSteps(int n) {
        return new EngineOptions(maxFirings, actionTimeout, maxProofDepth, maxAnswers, n, maxDerivationDepth);
    }

    public EngineOptions withMaxDerivationDepth(int n) {
        return new EngineOptions(maxFirings, actionTimeout, maxProofDepth, maxAnswers, maxQuestionSteps, n);
    }
}
