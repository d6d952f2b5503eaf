package org.kicnp.core;

import static java.util.Objects.requireNonNull;

/**
 * A slot as a frame sees it after inheritance: the merged {@link Slot}, the frame that declares its lowest
 * definition ({@code declaredBy}), and the frame whose value or default it carries ({@code valueFrom}, the same as
 * {@code declaredBy} when no frame gives a value).
 */
public record EffectiveSlot(Slot slot, String declaredBy, String valueFrom) {
    public EffectiveSlot {
        requireNonNull(slot, "slot");
        requireNonNull(declaredBy, "declaredBy");
        requireNonNull(valueFrom, "valueFrom");
    }

    /** Whether the slot is declared on an ancestor rather than on the frame asked about. */
    public boolean inheritedBy(String frame) {
        return !declaredBy.equals(frame);
    }
}
