package org.kicnp.robots;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Encodes {@link SimRequest}s and decodes {@link SimEvent}s of the {@code kicnp-sim/1} JSON-lines protocol. The
 * mapping is explicit (no annotations on the records), and decoding checks every member it reads, so a malformed
 * line is one {@link SimProtocolException} that quotes it rather than a null deep inside a listener.
 */
public final class SimCodec {
    /**
     * Characters (code points) of one line, either way (robots-sim/PROTOCOL.md). Jackson refuses a string longer than
     * 20,000,000 UTF-16 units, so a longer event would be dropped and the request it answers left to its timeout; a
     * line of half that many code points cannot hold such a string.
     */
    public static final int MAX_LINE = 10_000_000;
    private static final int MAX_QUOTE = 200;

    private final ObjectMapper json = new ObjectMapper();

    /**
     * The request as one JSON line (without the newline), carrying {@code id}.
     *
     * @throws IllegalArgumentException when the line would be longer than {@link #MAX_LINE}: the simulator would
     *     refuse it, as what it says back could not be read here
     */
    public String encode(String id, SimRequest request) {
        String line = line(id, request);
        if (tooLong(line)) {
            String what = request instanceof SimRequest.Command c ? c.robot() + "." + c.action() : request.type();
            throw new IllegalArgumentException("The simulator request '" + id + "' (" + what + ") would be a line of "
                    + line.codePointCount(0, line.length()) + " characters, longer than the protocol's limit of "
                    + MAX_LINE + " characters; it was not sent.");
        }
        return line;
    }

    private static boolean tooLong(String line) {
        return line.length() > MAX_LINE && line.codePointCount(0, line.length()) > MAX_LINE;
    }

    private String line(String id, SimRequest request) {
        ObjectNode out = json.createObjectNode();
        out.put("id", id);
        out.put("type", request.type());
        switch (request) {
            case SimRequest.Command c -> {
                out.put("robot", c.robot());
                out.put("action", c.action());
                out.set("args", json.valueToTree(c.args()));
                c.timeoutS().ifPresent(v -> out.put("timeout_s", v));
                c.progressS().ifPresent(v -> out.put("progress_s", v));
            }
            case SimRequest.SpawnUser s -> {
                out.put("name", s.name());
                out.put("x", s.x());
                out.put("y", s.y());
                out.put("heading_deg", s.headingDeg());
                s.face().ifPresent(f -> out.set("face", json.valueToTree(f)));
            }
            case SimRequest.MoveUser m -> {
                out.put("name", m.name());
                out.put("x", m.x());
                out.put("y", m.y());
                m.headingDeg().ifPresent(v -> out.put("heading_deg", v));
                m.speed().ifPresent(v -> out.put("speed", v));
            }
            case SimRequest.RemoveUser r -> out.put("name", r.name());
            case SimRequest.PlaceRobot p -> {
                out.put("robot", p.robot());
                out.put("x", p.x());
                out.put("y", p.y());
                out.put("heading_deg", p.headingDeg());
            }
            case SimRequest.AddObstacle o -> {
                out.put("name", o.name());
                out.put("x", o.x());
                out.put("y", o.y());
                out.put("w", o.w());
                out.put("h", o.h());
            }
            case SimRequest.Cancel c -> {
                out.put("robot", c.robot());
                out.put("action_id", c.actionId());
            }
            case SimRequest.Query q -> { }
            case SimRequest.Stream s -> {
                out.put("enabled", s.enabled());
                out.put("period_ms", s.periodMs());
            }
            case SimRequest.Step s -> {
                out.put("seconds", s.seconds());
                out.put("until_idle", s.untilIdle());
            }
            case SimRequest.SetTimeScale s -> out.put("time_scale", s.timeScale());
            case SimRequest.Shutdown s -> { }
        }
        return out.toString();
    }

    /** Decodes one line of the simulator's stdout. */
    public SimEvent decode(String line) {
        if (tooLong(line)) {
            throw bad(line, "it is " + line.codePointCount(0, line.length()) + " characters long, longer than the "
                    + "protocol's limit of " + MAX_LINE + " characters; it is skipped, and a request it answers fails "
                    + "when it times out");
        }
        JsonNode node;
        try {
            node = json.readTree(line);
        } catch (JsonProcessingException e) {
            throw bad(line, "it is not JSON (" + e.getOriginalMessage() + ")");
        }
        if (node == null || !node.isObject()) {
            throw bad(line, "it is not a JSON object");
        }
        Reader r = new Reader(node, line);
        String type = r.text("type");
        double t = r.number("t");
        return switch (type) {
            case "hello" -> new SimEvent.Hello(t, r.text("protocol"), r.node("seed").asLong(), r.text("mode"),
                    r.node("robots"));
            case "ack" -> new SimEvent.Ack(t, r.text("id"), r.optionalNode("result"));
            case "error" -> new SimEvent.Error(t, r.optionalText("id"), r.optionalText("field"), r.text("message"));
            case "action_started" -> new SimEvent.ActionStarted(t, r.text("id"), r.text("robot"), r.text("action"),
                    r.node("args"));
            case "action_progress" -> new SimEvent.ActionProgress(t, r.text("id"), r.text("robot"), r.text("action"),
                    r.optionalNode("fraction").map(JsonNode::asDouble), node);
            case "action_ended" -> new SimEvent.ActionEnded(t, r.text("id"), r.text("robot"), r.text("action"),
                    r.node("result"));
            case "action_failed" -> new SimEvent.ActionFailed(t, r.text("id"), r.text("robot"), r.text("action"),
                    r.text("reason"));
            case "sensor" -> sensor(t, r);
            case "utterance" -> new SimEvent.Utterance(t, r.text("robot"), r.text("id"), r.text("text"),
                    r.number("duration_s"));
            case "state" -> new SimEvent.State(t, r.optionalText("id"), node);
            default -> throw bad(line, "its type '" + type + "' is unknown");
        };
    }

    private SimEvent sensor(double t, Reader r) {
        String robot = r.text("robot");
        String sensor = r.text("sensor");
        return switch (sensor) {
            case "face_seen", "face_lost" -> new SimEvent.Face(t, robot, sensor.equals("face_seen"), r.text("track"),
                    r.number("bearing_deg"), r.number("distance_m"), r.numbers("face"), r.optionalText("truth_user"));
            case "bumper" -> new SimEvent.Bumper(t, robot, (int) r.number("bumper"), r.bool("pressed"),
                    r.optionalText("contact"));
            case "arrival" -> new SimEvent.Arrival(t, robot, r.number("x"), r.number("y"), r.number("heading_deg"),
                    r.optionalText("user"));
            case "fall" -> new SimEvent.Fall(t, robot, r.optionalText("contact").orElse("something"));
            default -> throw bad(r.line, "its sensor '" + sensor + "' is unknown");
        };
    }

    /** The JSON tree of a map of command arguments, for feedback details. */
    public String toJson(Object value) {
        return json.valueToTree(value).toString();
    }

    static SimProtocolException bad(String line, String why) {
        String quoted = line.length() > MAX_QUOTE ? line.substring(0, MAX_QUOTE) + "..." : line;
        return new SimProtocolException("Simulator line '" + quoted + "' is not a valid event: " + why + ".");
    }

    /** Reads members of one event, failing with the line quoted. */
    private record Reader(JsonNode node, String line) {
        JsonNode node(String name) {
            JsonNode v = node.get(name);
            if (v == null || v.isNull()) {
                throw bad(line, "member '" + name + "' is missing");
            }
            return v;
        }

        Optional<JsonNode> optionalNode(String name) {
            JsonNode v = node.get(name);
            return v == null || v.isNull() ? Optional.empty() : Optional.of(v);
        }

        String text(String name) {
            JsonNode v = node(name);
            if (!v.isTextual()) {
                throw bad(line, "member '" + name + "' is not a string");
            }
            return v.asText();
        }

        Optional<String> optionalText(String name) {
            return optionalNode(name).map(v -> {
                if (!v.isTextual()) {
                    throw bad(line, "member '" + name + "' is not a string");
                }
                return v.asText();
            });
        }

        double number(String name) {
            JsonNode v = node(name);
            if (!v.isNumber()) {
                throw bad(line, "member '" + name + "' is not a number");
            }
            return v.asDouble();
        }

        boolean bool(String name) {
            JsonNode v = node(name);
            if (!v.isBoolean()) {
                throw bad(line, "member '" + name + "' is not a boolean");
            }
            return v.asBoolean();
        }

        List<Double> numbers(String name) {
            JsonNode v = node(name);
            if (!(v instanceof ArrayNode array)) {
                throw bad(line, "member '" + name + "' is not an array");
            }
            List<Double> out = new ArrayList<>(array.size());
            for (JsonNode item : array) {
                if (!item.isNumber()) {
                    throw bad(line, "member '" + name + "' holds a non-number");
                }
                out.add(item.asDouble());
            }
            return out;
        }
    }
}
