package org.kicnp.core.xml;

import static java.util.Objects.requireNonNull;

import org.kicnp.core.Frame;

/** A frame read from XML together with where its FRAME element starts, so later checks can point back at it. */
public record SourcedFrame(Frame frame, SourceLocation location) {
    public SourcedFrame {
        requireNonNull(frame, "frame");
        requireNonNull(location, "location");
    }
}
