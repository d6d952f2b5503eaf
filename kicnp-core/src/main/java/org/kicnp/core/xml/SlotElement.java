package org.kicnp.core.xml;

import java.util.EnumMap;
import java.util.Optional;

/** A SLOT element as read: its facet elements by tag, and where it starts. */
record SlotElement(int line, int column, EnumMap<SlotTag, Located> facets) {

    Optional<Located> facet(SlotTag tag) {
        return Optional.ofNullable(facets.get(tag));
    }

    /** The facet if it is given and not empty or NULL. */
    Optional<Located> present(SlotTag tag) {
        Located l = facets.get(tag);
        return l == null || l.absent() ? Optional.empty() : Optional.of(l);
    }
}
