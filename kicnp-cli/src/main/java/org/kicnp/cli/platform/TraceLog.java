package org.kicnp.cli.platform;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameEvent;
import org.kicnp.core.KnowledgeListener;
import org.kicnp.core.Value;
import org.kicnp.inference.TraceEvent;
import org.kicnp.inference.TraceListener;

/**
 * Feeds the event log from the inference engine's trace (facts, firings, actions, failed scripts, retractions) and
 * from the knowledge base (sensor signals from the robots; Robovie's {@code utterance} signal is the robots' speech
 * as it is heard).
 */
final class TraceLog implements TraceListener, KnowledgeListener {
    private final EventLog log;

    TraceLog(EventLog log) {
        this.log = log;
    }

    @Override public void trace(TraceEvent event) {
        switch (event) {
            case TraceEvent.FactAsserted a -> log.record("fact", Map.of("instance", a.instance(), "class", a.className()));
            case TraceEvent.Fired f -> log.record("fired", Map.of("frame", f.frame(), "instance", f.instance(),
                    "binding", f.binding(), "firing", f.firing()));
            case TraceEvent.ActionIssued a -> log.record("action", Map.of("id", a.action().id(),
                    "robot", a.action().robot(), "name", a.action().name(), "args", a.action().args(),
                    "frame", a.action().frame(), "status", "issued"));
            case TraceEvent.ActionChanged c -> log.record("action", Map.of("id", c.actionId(),
                    "status", c.status().name().toLowerCase(java.util.Locale.ROOT), "detail", c.detail()));
            case TraceEvent.ScriptFailed s -> log.record("script_failed", Map.of("frame", s.frame(), "slot", s.slot(),
                    "instance", s.instance(), "message", s.message()));
            case TraceEvent.Retracted r -> log.record("retracted", Map.of("instance", r.instance(), "reason", r.reason()));
            case TraceEvent.Blocked b -> log.record("blocked", Map.of("frame", b.frame(), "binding", b.binding(),
                    "reason", b.reason()));
            case TraceEvent.LimitReached l -> log.record("limit", Map.of("limit", l.limit(), "frames", l.topFrames(),
                    "message", l.message()));
            default -> { }
        }
    }

    @Override public void changed(ChangeSet changes) {
        for (FrameEvent e : changes.events()) {
            if (e instanceof FrameEvent.Removed) {
                continue;
            }
            Frame f = e.frame();
            if (!f.isInstance() || !"SensorSignal".equals(f.parent().orElse(""))) {
                continue;
            }
            String source = text(f, "source");
            String sensor = text(f, "sensor");
            Map<String, Object> fields = new LinkedHashMap<>();
            fields.put("robot", source);
            fields.put("sensor", sensor);
            fields.put("values", f.ownSlot("values").flatMap(s -> s.value())
                    .map(v -> v instanceof Value.Lst l ? l.items().stream().map(Value::text).toList() : List.of(v.text()))
                    .orElse(List.of()));
            log.record("utterance".equals(sensor) ? "utterance" : "signal", fields);
        }
    }

    private static String text(Frame f, String slot) {
        return f.ownSlot(slot).flatMap(s -> s.value()).map(Value::text).orElse("");
    }
}
