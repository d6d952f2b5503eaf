package org.kicnp.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Instant;
import java.util.Locale;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;
import org.kicnp.protocol.FrameText;
import org.kicnp.protocol.Message;

/**
 * The JSON that {@code kicnp agent} prints, one shape per protocol record, as its subcommands' help describes them:
 * what {@code watch} hears, {@code prove}'s proofs, {@code why}'s reasons and {@code command}'s feedback.
 */
final class AgentJson {
    private static final ObjectMapper JSON = new ObjectMapper();

    private AgentJson() {
    }

    /** A value as indented JSON, for a whole answer printed at once. */
    static String pretty(Object value) {
        try {
            return JSON.writerWithDefaultPrettyPrinter().writeValueAsString(value);
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new IllegalStateException("Could not print the answer as JSON: " + e.getOriginalMessage(), e);
        }
    }

    /** One JSON line: a change of a watched class, with the frame's slots where the server sent the frame. */
    static String change(Message.Changed c) {
        ObjectNode o = JSON.createObjectNode();
        o.put("time", Instant.now().toString());
        o.put("event", c.change().name().toLowerCase(Locale.ROOT));
        o.put("class", c.ofClass());
        o.put("name", c.name());
        c.frame().ifPresent(xml -> {
            for (Frame f : FrameText.parse(xml, "change of '" + c.name() + "'", KnowledgeBase.create())) {
                o.put("frame_class", f.parent().orElse(null));
                ObjectNode slots = o.putObject("slots");
                for (Slot s : f.slots()) {
                    s.value().ifPresent(v -> slots.put(s.name(), v.text()));
                }
            }
        });
        return o.toString();
    }

    /** One JSON line: a message relayed to this agent. */
    static String relay(Message.Relay r) {
        ObjectNode o = JSON.createObjectNode();
        o.put("time", Instant.now().toString());
        o.put("event", "relay");
        o.put("from", r.from());
        o.put("subject", r.subject());
        o.put("body", r.body());
        return o.toString();
    }

    /** A proof tree: {ofClass, instance (when it exists), slots: {slot: proof}, assumptions}. */
    static ObjectNode proof(Message.ProofNode p) {
        ObjectNode o = JSON.createObjectNode();
        o.put("ofClass", p.ofClass());
        p.instance().ifPresent(i -> o.put("instance", i));
        ObjectNode slots = o.putObject("slots");
        p.slots().forEach((slot, sub) -> slots.set(slot, proof(sub)));
        ArrayNode assumed = o.putArray("assumptions");
        p.assumptions().forEach(assumed::add);
        return o;
    }

    /** Why a behavior frame has not fired: {frame, summary, slots: [...], bindings: [...], truncated}. */
    static ObjectNode notFired(Message.NotFired n) {
        ObjectNode o = JSON.createObjectNode();
        o.put("frame", n.frame());
        o.put("summary", n.summary());
        o.set("slots", JSON.valueToTree(n.slots()));
        o.set("bindings", JSON.valueToTree(n.bindings()));
        o.put("truncated", n.truncated());
        return o;
    }

    /** Why an instance exists: {instance, ofClass, derived, binding, conditions, supports: [...]}. */
    static ObjectNode reason(Message.Reason r) {
        ObjectNode o = JSON.createObjectNode();
        o.put("instance", r.instance());
        o.put("ofClass", r.ofClass());
        o.put("derived", r.derived());
        ObjectNode binding = o.putObject("binding");
        r.binding().forEach(binding::put);
        ArrayNode conditions = o.putArray("conditions");
        r.conditions().forEach(conditions::add);
        ArrayNode supports = o.putArray("supports");
        r.supports().forEach(s -> supports.add(reason(s)));
        return o;
    }

    /** One JSON line: a feedback of a command, {id, robot, stage, progress (when given), detail}. */
    static String feedback(Message.Feedback f) {
        ObjectNode o = JSON.createObjectNode();
        o.put("id", f.id());
        o.put("robot", f.robot());
        o.put("stage", f.stage().name().toLowerCase(Locale.ROOT));
        f.progress().ifPresent(p -> o.put("progress", p));
        o.put("detail", f.detail());
        return o.toString();
    }
}
