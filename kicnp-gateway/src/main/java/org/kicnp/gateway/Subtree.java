package org.kicnp.gateway;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;

/** The durable frames of a subtree (a root and every frame below it) or of a whole knowledge base, parents first. */
final class Subtree {
    private Subtree() {
    }

    static List<Frame> of(KnowledgeBase kb, Optional<String> root) {
        Map<String, Frame> chosen = new LinkedHashMap<>();
        for (Frame f : kb.frames()) {
            if (f.provenance().durable() && root.map(r -> kb.isA(f.name(), r)).orElse(true)) {
                chosen.put(f.name(), f);
            }
        }
        return parentsFirst(chosen);
    }

    /**
     * The frames in knowledge base order, except that a frame comes after its parent: a frame keeps its place when
     * it is replaced, so one moved below a class added after it would otherwise come first.
     */
    private static List<Frame> parentsFirst(Map<String, Frame> frames) {
        List<Frame> out = new ArrayList<>(frames.size());
        Set<String> placed = new HashSet<>(frames.size() * 2);
        Deque<Frame> chain = new ArrayDeque<>();
        for (Frame f : frames.values()) {
            // The knowledge base has no IS-A cycles; stopping at a frame already on the chain is only a guard.
            Set<String> onChain = new HashSet<>();
            for (Frame up = f; up != null && !placed.contains(up.name()) && onChain.add(up.name()); ) {
                chain.push(up);
                up = up.parent().map(frames::get).orElse(null);
            }
            while (!chain.isEmpty()) {
                Frame next = chain.pop();
                if (placed.add(next.name())) {
                    out.add(next);
                }
            }
        }
        return out;
    }
}
