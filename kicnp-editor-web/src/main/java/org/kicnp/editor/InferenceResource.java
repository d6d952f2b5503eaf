package org.kicnp.editor;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.inference.AgendaEntry;
import org.kicnp.inference.InferenceEngine;
import org.kicnp.inference.InferenceLimitException;
import org.kicnp.inference.TraceListener;

/**
 * The editor's view of a running inference engine: the live (runtime) instances in working memory and whether the
 * engine derived them, the agenda size, "why does this instance exist", "which instances of this class are there
 * or could there be" (backward chaining), "why has this behavior frame not fired", a run to quiescence, and every trace event pushed to the page over
 * {@code /api/events} as {@code {"type":"trace", ...}}.
 */
final class InferenceResource implements Features.Inference {
    private final InferenceEngine engine;
    private final KnowledgeBase kb;
    private TraceListener tracer;

    InferenceResource(InferenceEngine engine, KnowledgeBase kb) {
        this.engine = engine;
        this.kb = kb;
    }

    @Override public boolean available() {
        return true;
    }

    @Override public synchronized void attach(EventHub events) {
        // On the engine's thread, for every trace event: no page connected, no JSON made.
        tracer = e -> {
            if (events.clientCount() > 0) {
                events.publish("trace", InferenceJson.trace(e));
            }
        };
        engine.addTraceListener(tracer);
    }

    @Override public Object status() {
        List<Map<String, Object>> instances = new ArrayList<>();
        for (Frame f : kb.frames()) {
            if (f.isInstance() && f.provenance() == Provenance.RUNTIME) {
                Map<String, Object> row = new LinkedHashMap<>();
                row.put("name", f.name());
                row.put("className", f.parent().orElse(""));
                row.put("derived", engine.derivation(f.name()).isPresent());
                instances.add(row);
            }
        }
        Map<String, Object> out = new LinkedHashMap<>();
        List<Map<String, Object>> activations = new ArrayList<>();
        for (AgendaEntry a : engine.agenda()) {
            Map<String, Object> row = new LinkedHashMap<>();
            row.put("frame", a.frame());
            row.put("binding", new java.util.TreeMap<>(a.binding()));
            row.put("priority", a.priority());
            row.put("depth", a.depth());
            row.put("recency", a.recency());
            activations.add(row);
        }
        out.put("agenda", activations.size());
        out.put("activations", activations);
        out.put("version", kb.version());
        out.put("instances", instances);
        out.put("actions", engine.actions().size());
        return out;
    }

    @Override public Object why(String instance) {
        if (!kb.require(instance).isInstance()) {
            // The engine would explain a class as an instance nobody derived; there is no such instance to explain.
            throw new ApiException(404, "Frame '" + instance + "' is a class; why explains instances only.");
        }
        return InferenceJson.explanation(engine.why(instance));
    }

    @Override public Object ask(String className) {
        requireClass(className, "ask");
        return InferenceJson.answers(engine.ask(className, Map.of()));
    }

    @Override public Object prove(String className) {
        requireClass(className, "prove");
        return engine.prove(className, Map.of()).stream().map(InferenceJson::proof).toList();
    }

    @Override public Object whyNot(String frame) {
        kb.require(frame);
        try {
            return InferenceJson.whyNot(engine.whyNot(frame, Map.of()));
        } catch (IllegalArgumentException e) {
            throw new ApiException(422, e.getMessage());
        }
    }

    /** Backward chaining answers with instances of a class: an instance has none, so it would answer nothing. */
    private void requireClass(String name, String what) {
        if (kb.require(name).isInstance()) {
            throw new ApiException(404, "Frame '" + name + "' is an instance; " + what + " takes a class.");
        }
    }

    @Override public Set<String> destroy(String instance) {
        return engine.destroy(instance);
    }

    @Override public Object run() {
        try {
            int firings = engine.runToQuiescence();
            return Map.of("firings", firings, "agenda", engine.agendaSize(), "version", kb.version());
        } catch (InferenceLimitException e) {
            throw new ApiException(422, e.getMessage());
        }
    }

    @Override public synchronized void close() {
        if (tracer != null) {
            engine.removeTraceListener(tracer);
            tracer = null;
        }
    }
}
