package org.kicnp.core.store;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameEvent;

/**
 * One committed batch as the journal keeps it: the knowledge base version and the operations that bring the
 * durable frames from the state before the batch to the state after it. Operations are idempotent (put the whole
 * frame, delete by name), so replaying a record whose effect is already in the XML files changes nothing.
 */
record JournalRecord(long version, List<Op> ops) {

    JournalRecord {
        ops = List.copyOf(ops);
    }

    /** An idempotent change to the durable frames. */
    sealed interface Op permits Put, Delete {
        String name();
    }

    /** The frame as it is now: added or replacing whatever has the name. */
    record Put(Frame frame) implements Op {
        Put {
            requireNonNull(frame, "frame");
        }

        @Override public String name() {
            return frame.name();
        }
    }

    /** No durable frame has this name any more. */
    record Delete(String name) implements Op {
        Delete {
            requireNonNull(name, "name");
        }
    }

    /**
     * The record of a batch. A frame replaced by a runtime (non-durable) frame is deleted from storage, and a runtime
     * frame turned durable is put: only what should survive a restart is written.
     */
    static JournalRecord of(long version, List<FrameEvent> events) {
        List<Op> ops = new ArrayList<>(events.size());
        for (FrameEvent e : events) {
            ops.add(switch (e) {
                case FrameEvent.Removed r -> new Delete(r.name());
                case FrameEvent.Added a -> durableOrDelete(a.frame());
                case FrameEvent.Replaced r -> durableOrDelete(r.frame());
            });
        }
        return new JournalRecord(version, ops);
    }

    private static Op durableOrDelete(Frame f) {
        return f.provenance().durable() ? new Put(f) : new Delete(f.name());
    }
}
