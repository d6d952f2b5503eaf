package org.kicnp.core.xml;

import java.util.Optional;

/**
 * A SLOT element as read: its facet elements by tag (an array by {@link SlotTag} ordinal, null where absent: a large
 * load reads hundreds of thousands of slots, and an array is a fraction of an EnumMap), and where it starts.
 */
record SlotElement(int line, int column, Located[] facets) {

    /** The facet element as read, or null. */
    Located get(SlotTag tag) {
        return facets[tag.ordinal()];
    }

    Optional<Located> facet(SlotTag tag) {
        return Optional.ofNullable(get(tag));
    }

    /** The facet if it is given and not empty or NULL. */
    Optional<Located> present(SlotTag tag) {
        Located l = get(tag);
        return l == null || l.absent() ? Optional.empty() : Optional.of(l);
    }
}
