package org.kicnp.protocol;

/** What happened to a frame, in a {@link Message.Changed} notification. */
public enum ChangeKind {
    ADDED,
    REPLACED,
    REMOVED
}
