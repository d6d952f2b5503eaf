package org.kicnp.core;

/** Table 1's "frame type": a class frame describes a kind of thing, an instance frame one thing of that kind. */
public enum FrameKind {
    CLASS,
    INSTANCE
}
