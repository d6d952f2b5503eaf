package org.kicnp.core;

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
}
