package org.kicnp.gateway;

import java.util.List;
import java.util.Optional;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;

/** The durable frames of a subtree (a root and every frame below it) or of a whole knowledge base, parents first. */
final class Subtree {
    private Subtree() {
    }

    static List<Frame> of(KnowledgeBase kb, Optional<String> root) {
        return kb.frames().stream()
                .filter(f -> f.provenance().durable())
                .filter(f -> root.map(r -> kb.isA(f.name(), r)).orElse(true))
                .toList();
    }
}
