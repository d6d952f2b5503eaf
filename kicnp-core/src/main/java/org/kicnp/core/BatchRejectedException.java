package org.kicnp.core;

import java.util.List;

/** A batch broke the rules of the frame model; nothing in it was applied. Carries every problem found. */
public final class BatchRejectedException extends InvalidFrameException {
    private final List<Problem> problems;

    public BatchRejectedException(List<Problem> problems) {
        super(summary(problems));
        this.problems = List.copyOf(problems);
    }

    public List<Problem> problems() {
        return problems;
    }

    private static String summary(List<Problem> problems) {
        if (problems.size() == 1) {
            return problems.getFirst().message();
        }
        StringBuilder sb = new StringBuilder(problems.size() + " problems; nothing was changed:");
        problems.stream().limit(20).forEach(p -> sb.append("\n  ").append(p.message()));
        if (problems.size() > 20) {
            sb.append("\n  ... and ").append(problems.size() - 20).append(" more.");
        }
        return sb.toString();
    }
}
