package org.kicnp.core;

import static java.util.Objects.requireNonNull;

/** A semantic link (Table 1) to or from another frame, typed by its relation. */
public record SemanticLink(Relation relation, String frame) {
    public SemanticLink {
        requireNonNull(relation, "relation");
        requireNonNull(frame, "frame");
    }
}
