package org.kicnp.core.xml;

import java.util.Optional;

/**
 * A mapped frame with the locations needed to point back at it when the knowledge base rejects the batch: its ISA
 * element and each slot's SLOT element, in the frame's slot order, packed as {@code line << 32 | column}.
 */
record ParsedFrame(SourcedFrame sourced, Optional<SourceLocation> isa, long[] slots) {

    /** The SLOT element of the named slot, or the FRAME element when there is no such slot. */
    SourceLocation slot(String name) {
        var own = sourced.frame().slots();
        for (int i = 0; i < own.size() && i < slots.length; i++) {
            if (own.get(i).name().equals(name)) {
                return new SourceLocation(sourced.location().source(), (int) (slots[i] >>> 32), (int) slots[i]);
            }
        }
        return sourced.location();
    }
}
