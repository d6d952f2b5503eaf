package org.kicnp.core;

import java.util.List;

/** The events of one committed batch, in the order the batch gave them, and the knowledge base version it made. */
public record ChangeSet(long version, List<FrameEvent> events) {
    public ChangeSet {
        events = List.copyOf(events);
    }

    public boolean isEmpty() {
        return events.isEmpty();
    }
}
