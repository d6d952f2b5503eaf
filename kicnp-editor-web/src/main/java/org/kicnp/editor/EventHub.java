package org.kicnp.editor;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.FrameEvent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeListener;
import org.kicnp.core.UnknownFrameException;

/**
 * Pushes knowledge-base changes to every connected page as JSON over the {@code /api/events} WebSocket. Each
 * committed batch becomes one message {@code {"type":"change","version":N,"events":[...]}}; other event types
 * (for example inference trace events) go through {@link #publish(String, Object)}.
 */
final class EventHub implements KnowledgeListener {
    /** One frame event on the wire: what happened and the frame's row as {@code GET /api/frames} lists it. */
    record Event(String kind, String name, FrameViews.Summary frame) {
    }

    private final KnowledgeBase kb;
    private final ObjectMapper json;
    private final Set<EventClient> clients = ConcurrentHashMap.newKeySet();

    EventHub(KnowledgeBase kb, ObjectMapper json) {
        this.kb = kb;
        this.json = json;
    }

    @Override public void changed(ChangeSet changes) {
        if (clients.isEmpty()) {
            return;
        }
        List<Event> events = changes.events().stream().map(this::event).toList();
        publish("change", Map.of("version", changes.version(), "events", events));
    }

    /** Sends {@code {"type": type, ...payload}} to every client. */
    void publish(String type, Object payload) {
        Map<String, Object> body = new java.util.LinkedHashMap<>();
        body.put("type", type);
        body.putAll(json.convertValue(payload, Map.class));
        String text;
        try {
            text = json.writeValueAsString(body);
        } catch (JsonProcessingException e) {
            throw new EditorException("An editor event could not be written as JSON: " + e.getMessage(), e);
        }
        clients.forEach(c -> c.send(text));
    }

    void joined(EventClient client) {
        clients.add(client);
        publishTo(client);
    }

    void left(EventClient client) {
        clients.remove(client);
    }

    int clientCount() {
        return clients.size();
    }

    private void publishTo(EventClient client) {
        try {
            client.send(json.writeValueAsString(Map.of("type", "hello", "version", kb.version())));
        } catch (JsonProcessingException e) {
            throw new EditorException("The hello event could not be written: " + e.getMessage(), e);
        }
    }

    private Event event(FrameEvent e) {
        String kind = switch (e) {
            case FrameEvent.Added a -> "added";
            case FrameEvent.Replaced r -> "replaced";
            case FrameEvent.Removed r -> "removed";
        };
        FrameViews.Summary row = null;
        if (!(e instanceof FrameEvent.Removed)) {
            try {
                row = kb.frame(e.name()).map(f -> FrameViews.summary(kb, f)).orElse(null);
            } catch (UnknownFrameException gone) {
                // Removed by a later batch before this one was delivered; that batch's event says so.
            }
        }
        return new Event(kind, e.name(), row);
    }
}
