package org.kicnp.inference;

import static java.util.Objects.requireNonNull;

import java.util.Map;

/**
 * One activation waiting on the agenda, as the outside sees it (the editor's inference view lists them): the behavior
 * frame, its binding (required slot → instance name), and the keys conflict resolution orders it by — the frame's
 * priority, its depth in the hierarchy, and the recency (assertion stamp of the newest fact in the binding).
 * A read-only copy: changing the engine afterwards does not change it.
 */
public record AgendaEntry(String frame, Map<String, String> binding, int priority, int depth, long recency) {
    public AgendaEntry {
        requireNonNull(frame, "frame");
        binding = Map.copyOf(binding);
    }

    static AgendaEntry of(Activation a) {
        return new AgendaEntry(a.rule().frame(), a.binding(), a.rule().priority(), a.rule().depth(), a.recency());
    }
}
