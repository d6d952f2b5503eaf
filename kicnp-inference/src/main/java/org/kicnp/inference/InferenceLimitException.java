package org.kicnp.inference;

import java.util.List;

/**
 * Thrown when one run to quiescence fires more often than the configured limit: the knowledge base is most likely
 * feeding itself. Names the frames that fired most, so the loop can be found.
 */
public final class InferenceLimitException extends InferenceException {
    private final List<String> topFrames;

    public InferenceLimitException(int limit, List<String> topFrames) {
        super("Inference stopped after " + limit + " firings without reaching quiescence; the frames firing most were "
                + String.join(", ", topFrames.stream().map(f -> "'" + f + "'").toList()) + ".");
        this.topFrames = List.copyOf(topFrames);
    }

    /** The frames that fired most in the stopped run's last 4,096 firings (or all of them), most frequent first. */
    public List<String> topFrames() {
        return topFrames;
    }
}
