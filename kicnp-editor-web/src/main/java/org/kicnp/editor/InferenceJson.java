package org.kicnp.editor;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.kicnp.inference.Action;
import org.kicnp.inference.Answer;
import org.kicnp.inference.Proof;
import org.kicnp.inference.Derivation;
import org.kicnp.inference.Explanation;
import org.kicnp.inference.TraceEvent;
import org.kicnp.inference.WhyNot;

/**
 * The inference engine's results as the page reads them: trace events, explanations ("why does this instance
 * exist") and answers. Mapped by hand with an exhaustive switch so that every new trace event kind is a compile
 * error here, and so the engine's types need no Jackson annotations. Each trace event also carries {@code text},
 * a one-line sentence for the trace log.
 */
final class InferenceJson {
    private InferenceJson() {
    }

    static Map<String, Object> trace(TraceEvent e) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("event", e.kind());
        switch (e) {
            case TraceEvent.FactAsserted f -> put(m, "instance", f.instance(), "className", f.className(),
                    "text", f.instance() + " asserted as " + f.className());
            case TraceEvent.FactChanged f -> put(m, "instance", f.instance(), "text", f.instance() + " changed");
            case TraceEvent.FactRemoved f -> put(m, "instance", f.instance(), "text", f.instance() + " removed");
            case TraceEvent.Matched t -> put(m, "frame", t.frame(), "binding", t.binding(),
                    "text", t.frame() + " matched " + t.binding());
            case TraceEvent.Activated t -> put(m, "frame", t.frame(), "binding", t.binding(), "agenda", t.agendaSize(),
                    "text", t.frame() + " activated " + t.binding() + "; agenda " + t.agendaSize());
            case TraceEvent.Blocked t -> put(m, "frame", t.frame(), "binding", t.binding(), "reason", t.reason(),
                    "text", t.frame() + " blocked: " + t.reason());
            case TraceEvent.Fired t -> put(m, "frame", t.frame(), "instance", t.instance(), "binding", t.binding(),
                    "firing", t.firing(), "text", "#" + t.firing() + " " + t.frame() + " fired, made " + t.instance());
            case TraceEvent.ScriptCalled t -> put(m, "frame", t.frame(), "slot", t.slot(), "instance", t.instance(),
                    "text", "script " + t.frame() + "." + t.slot() + " ran for " + t.instance());
            case TraceEvent.ScriptFailed t -> put(m, "frame", t.frame(), "slot", t.slot(), "instance", t.instance(),
                    "message", t.message(), "text", "script " + t.frame() + "." + t.slot() + " failed: " + t.message());
            case TraceEvent.Retracted t -> put(m, "instance", t.instance(), "reason", t.reason(),
                    "text", t.instance() + " retracted: " + t.reason());
            case TraceEvent.ActionIssued t -> put(m, "action", action(t.action()),
                    "text", "action " + t.action().id() + ": " + t.action().robot() + " " + t.action().name()
                            + " " + t.action().args());
            case TraceEvent.ActionChanged t -> put(m, "actionId", t.actionId(), "status", t.status().name(),
                    "detail", t.detail(), "text", "action " + t.actionId() + " " + t.status().name().toLowerCase()
                            + (t.detail() == null || t.detail().isEmpty() ? "" : ": " + t.detail()));
            case TraceEvent.LimitReached t -> put(m, "limit", t.limit(), "topFrames", t.topFrames(),
                    "text", t.message());
        }
        return m;
    }

    static Map<String, Object> explanation(Explanation e) {
        Map<String, Object> m = new LinkedHashMap<>();
        switch (e) {
            case Explanation.Asserted a -> put(m, "type", "asserted", "instance", a.instance(), "className", a.className());
            case Explanation.Derived d -> put(m, "type", "derived", "instance", d.instance(),
                    "derivation", derivation(d.derivation()),
                    "supports", d.supports().stream().map(InferenceJson::explanation).toList());
        }
        return m;
    }

    static Map<String, Object> derivation(Derivation d) {
        Map<String, Object> m = new LinkedHashMap<>();
        put(m, "frame", d.frame(), "binding", d.binding(), "firing", d.firing(), "trigger", d.trigger(),
                "createdBy", d.createdBy().orElse(""),
                "conditions", d.conditions().stream().map(c -> Map.of("slot", c.slot(), "condition", c.condition(),
                        "value", c.value())).toList());
        return m;
    }

    static Map<String, Object> answer(Answer a) {
        Map<String, Object> m = new LinkedHashMap<>();
        put(m, "className", a.className(), "instance", a.instance().orElse(""), "slots", a.slots(),
                "derivable", a.derivable());
        return m;
    }

    private static Map<String, Object> action(Action a) {
        Map<String, Object> m = new LinkedHashMap<>();
        put(m, "id", a.id(), "robot", a.robot(), "name", a.name(), "args", a.args(), "frame", a.frame(),
                "instance", a.instance());
        return m;
    }

    private static void put(Map<String, Object> m, Object... keysAndValues) {
        for (int i = 0; i < keysAndValues.length; i += 2) {
            m.put((String) keysAndValues[i], keysAndValues[i + 1]);
        }
    }

    /** A proof tree: an existing instance, or a frame that could derive one from the proofs of its slots. */
    static Map<String, Object> proof(Proof p) {
        Map<String, Object> m = new LinkedHashMap<>();
        switch (p) {
            case Proof.Exists e -> put(m, "kind", "exists", "className", e.className(), "instance", e.instance());
            case Proof.Derivable d -> {
                Map<String, Object> slots = new LinkedHashMap<>();
                d.slots().entrySet().stream().sorted(Map.Entry.comparingByKey())
                        .forEach(en -> slots.put(en.getKey(), proof(en.getValue())));
                put(m, "kind", "derivable", "className", d.className(), "slots", slots,
                        "assumptions", d.assumptions());
            }
        }
        m.put("depth", p.depth());
        return m;
    }

    static Map<String, Object> whyNot(WhyNot w) {
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("frame", w.frame());
        out.put("summary", w.summary());
        List<Map<String, Object>> slots = new ArrayList<>();
        for (WhyNot.SlotCandidates s : w.slots()) {
            Map<String, Object> row = new LinkedHashMap<>();
            row.put("slot", s.slot());
            row.put("argument", s.argument());
            row.put("condition", s.condition());
            row.put("candidates", s.candidates());
            row.put("rejected", s.rejected());
            row.put("candidateCount", s.candidateCount());
            row.put("rejectedCount", s.rejectedCount());
            slots.add(row);
        }
        out.put("slots", slots);
        List<Map<String, Object>> bindings = new ArrayList<>();
        for (WhyNot.Verdict v : w.bindings()) {
            Map<String, Object> row = new LinkedHashMap<>();
            row.put("binding", v.binding());
            row.put("outcome", v.outcome().name().toLowerCase(Locale.ROOT));
            row.put("reason", v.reason());
            bindings.add(row);
        }
        out.put("bindings", bindings);
        out.put("truncated", w.truncated());
        return out;
    }

    static List<Map<String, Object>> answers(List<Answer> answers) {
        return answers.stream().map(InferenceJson::answer).toList();
    }
}
