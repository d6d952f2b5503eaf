package org.kicnp.core;

import java.util.ArrayList;
import java.util.List;

/**
 * Makes a batch durable before it becomes visible. The knowledge base calls {@link #append} under its write lock,
 * after validation and before changing memory; if it throws, the batch fails and nothing changes. Only events of
 * durable frames ({@link Provenance#durable()}) are passed.
 */
@FunctionalInterface
public interface CommitLog {
    /** A log that keeps nothing: the knowledge base lives in memory only. */
    CommitLog NONE = (version, events) -> { };

    void append(long version, List<FrameEvent> durableEvents);

    /** The events the commit log must keep: those of frames kept on disk before or after the change. */
    static List<FrameEvent> durableEvents(List<FrameEvent> events) {
        List<FrameEvent> out = null;
        for (int i = 0, n = events.size(); i < n; i++) {
            FrameEvent e = events.get(i);
            boolean durable = e.frame().provenance().durable()
                    || e instanceof FrameEvent.Replaced r && r.before_().provenance().durable();
            if (durable) {
                if (out == null) {
                    out = new ArrayList<>(n - i);
                }
                out.add(e);
            }
        }
        return out == null ? List.of() : out;
    }
}
