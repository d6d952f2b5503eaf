package org.kicnp.inference;

/**
 * Thrown by backward chaining ({@code ask}, {@code prove}) when a question would try more combinations of instances
 * than {@link EngineOptions#maxQuestionSteps} allows: the engine is held while it answers, so a question over many
 * instances must not hold it for minutes. Holding some slots fixed (partial bindings) narrows it.
 */
public final class QuestionTooBroadException extends InferenceException {
    public QuestionTooBroadException(String className, int steps) {
        super("The question about '" + className + "' is too broad: it tried " + String.format("%,d", steps)
                + " combinations of instances without finishing (the engine's maxQuestionSteps); hold some of the "
                + "slots fixed to narrow it.");
    }
}
