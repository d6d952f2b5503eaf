package org.kicnp.core;

import java.util.Optional;

/** What a committed change did to one frame, as published to {@link KnowledgeListener}s. */
public sealed interface FrameEvent permits FrameEvent.Added, FrameEvent.Replaced, FrameEvent.Removed {

    /** The frame's name. */
    default String name() {
        return frame().name();
    }

    /** The frame as it is after the change, or as it was when removed. */
    Frame frame();

    /** The frame before the change, where there was one. */
    Optional<Frame> before();

    record Added(Frame frame) implements FrameEvent {
        @Override public Optional<Frame> before() {
            return Optional.empty();
        }
    }

    record Replaced(Frame before_, Frame frame) implements FrameEvent {
        @Override public Optional<Frame> before() {
            return Optional.of(before_);
        }
    }

    record Removed(Frame frame) implements FrameEvent {
        @Override public Optional<Frame> before() {
            return Optional.of(frame);
        }
    }
}
