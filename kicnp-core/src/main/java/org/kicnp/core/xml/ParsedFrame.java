package org.kicnp.core.xml;

import java.util.List;
import java.util.Optional;

/**
 * A mapped frame with the locations needed to point back at it when the knowledge base rejects the batch: its ISA
 * element and each slot's SLOT element, in the frame's slot order.
 */
record ParsedFrame(SourcedFrame sourced, Optional<SourceLocation> isa, List<SourceLocation> slots) {

    /** The SLOT element of the named slot, or the FRAME element when there is no such slot. */
    SourceLocation slot(String name) {
        var own = sourced.frame().slots();
        for (int i = 0; i < own.size() && i < slots.size(); i++) {
            if (own.get(i).name().equals(name)) {
                return slots.get(i);
            }
        }
        return sourced.location();
    }
}
