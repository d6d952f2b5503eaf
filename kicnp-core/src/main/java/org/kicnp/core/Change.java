package org.kicnp.core;

import static java.util.Objects.requireNonNull;

/** One change in a batch given to {@link KnowledgeBase#apply}. A batch applies all or nothing. */
public sealed interface Change permits Change.Add, Change.Replace, Change.Put, Change.Remove {

    /** Revision value meaning "replace whatever revision is there". */
    long ANY_REVISION = -1;

    /** The name of the frame this change touches. */
    String name();

    /** Adds a frame; fails if a frame of that name exists. */
    record Add(Frame frame) implements Change {
        public Add {
            requireNonNull(frame, "frame");
        }

        @Override public String name() {
            return frame.name();
        }
    }

    /**
     * Replaces an existing frame of the same name. With an expected revision other than {@link #ANY_REVISION} the
     * replace fails if the frame changed since that revision was read (two editors saving one frame).
     */
    record Replace(Frame frame, long expectedRevision) implements Change {
        public Replace {
            requireNonNull(frame, "frame");
        }

        public Replace(Frame frame) {
            this(frame, ANY_REVISION);
        }

        @Override public String name() {
            return frame.name();
        }
    }

    /** Adds the frame, or replaces the one of that name: used for journal replay and frames pushed between servers. */
    record Put(Frame frame) implements Change {
        public Put {
            requireNonNull(frame, "frame");
        }

        @Override public String name() {
            return frame.name();
        }
    }

    /**
     * Removes a frame; fails while it has subclasses or instances or other frames refer to it. With an expected
     * revision other than {@link #ANY_REVISION} the removal fails if the frame changed since that revision was read
     * (a reading that expires must not take a newer reading of the same sensor with it).
     */
    record Remove(String name, long expectedRevision) implements Change {
        public Remove {
            requireNonNull(name, "name");
        }

        public Remove(String name) {
            this(name, ANY_REVISION);
        }
    }
}
