package org.kicnp.inference;

import java.util.List;

/**
 * Thrown when one run to quiescence fires more often in a row than the configured limit, or would derive an instance
 * resting on a longer chain of derived instances than allowed: the knowledge base is most likely feeding itself. Names
 * the frames that fired most, so the loop can be found.
 */
public final class InferenceLimitException extends InferenceException {
    private final List<String> topFrames;

    public InferenceLimitException(int limit, List<String> topFrames) {
        this("Inference stopped after " + limit + " firings without reaching quiescence; the frames firing most were "
                + quoted(topFrames) + ".", topFrames);
    }

    private InferenceLimitException(String message, List<String> topFrames) {
        super(message);
        this.topFrames = List.copyOf(topFrames);
    }

    /**
     * A firing of {@code frame} would have made an instance resting on derived instances more than {@code limit} deep
     * (each made from the one before): a knowledge base feeding itself, stopped however often changes come in from
     * outside, which start the count of firings in a row again.
     */
    static InferenceLimitException deeperThan(int limit, String frame, List<String> topFrames) {
        return new InferenceLimitException("Inference stopped: '" + frame + "' would derive an instance resting on "
                + String.format("%,d", limit) + " derived instances, each made from the one before, so the knowledge "
                + "base feeds itself; the frames firing most were " + quoted(topFrames) + ".", topFrames);
    }

    private static String quoted(List<String> frames) {
        return String.join(", ", frames.stream().map(f -> "'" + f + "'").toList());
    }

    /** The frames that fired most in the stopped run's last 4,096 firings (or all of them), most frequent first. */
    public List<String> topFrames() {
        return topFrames;
    }
}
