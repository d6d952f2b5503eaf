package org.kicnp.editor;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.BiConsumer;
import org.kicnp.editor.WorldSnapshot.Box;
import org.kicnp.editor.WorldSnapshot.Point;
import org.kicnp.editor.WorldSnapshot.Room;

/**
 * Maps the simulator's JSON events (robots-sim/PROTOCOL.md, {@code kicnp-sim/1}) onto the editor's
 * {@link WorldSnapshot}: {@link #room(JsonNode)} reads the room from {@code hello}, {@link #snapshot(JsonNode, Room)}
 * turns one {@code state} event into a snapshot, so a {@link WorldView} over the simulator is a few lines.
 */
public final class SimulatorState {
    private SimulatorState() {
    }

    /** The room of a {@code hello} event ({@code room.width/height/door/counter}); the simulator's default when absent. */
    public static Room room(JsonNode hello) {
        JsonNode room = hello.path("room");
        if (!room.isObject()) {
            return Room.SIMULATOR;
        }
        JsonNode door = room.path("door");
        JsonNode counter = room.path("counter");
        Room d = Room.SIMULATOR;
        return new Room(room.path("width").asDouble(d.width()), room.path("height").asDouble(d.height()),
                new Point(door.path("x").asDouble(d.door().x()), door.path("y").asDouble(d.door().y())),
                new Box(counter.path("x0").asDouble(d.counter().x0()), counter.path("y0").asDouble(d.counter().y0()),
                        counter.path("x1").asDouble(d.counter().x1()), counter.path("y1").asDouble(d.counter().y1())));
    }

    /**
     * One {@code state} event as a snapshot in {@code room}.
     *
     * @throws IllegalArgumentException when the event is not a {@code state} event
     */
    public static WorldSnapshot snapshot(JsonNode state, Room room) {
        if (!"state".equals(state.path("type").asText())) {
            throw new IllegalArgumentException("A world snapshot is made from a 'state' event, not from '"
                    + state.path("type").asText() + "'.");
        }
        List<WorldSnapshot.Robot> robots = new ArrayList<>();
        each(state.path("robots"), (name, r) -> robots.add(new WorldSnapshot.Robot(name, r.path("kind").asText(""),
                r.path("x").asDouble(), r.path("y").asDouble(), r.path("heading_deg").asDouble(), actions(r),
                stateText(r))));
        List<WorldSnapshot.User> users = new ArrayList<>();
        each(state.path("users"), (name, u) -> users.add(new WorldSnapshot.User(name, u.path("x").asDouble(),
                u.path("y").asDouble(), u.path("heading_deg").asDouble())));
        List<WorldSnapshot.Cup> cups = new ArrayList<>();
        each(state.path("cups"), (name, c) -> cups.add(new WorldSnapshot.Cup(name, c.path("kind").asText(""),
                c.path("x").asDouble(), c.path("y").asDouble(), c.path("holder").isTextual()
                        ? c.path("holder").asText() : "")));
        List<WorldSnapshot.Obstacle> obstacles = new ArrayList<>();
        each(state.path("obstacles"), (name, o) -> obstacles.add(new WorldSnapshot.Obstacle(name,
                o.path("x").asDouble(), o.path("y").asDouble(), o.path("w").asDouble(), o.path("h").asDouble())));
        return new WorldSnapshot(state.path("t").asDouble(), room, robots, users, cups, obstacles);
    }

    private static List<WorldSnapshot.RunningAction> actions(JsonNode robot) {
        List<WorldSnapshot.RunningAction> out = new ArrayList<>();
        each(robot.path("actions"), (part, a) -> out.add(new WorldSnapshot.RunningAction(part,
                a.path("id").asText(""), a.path("action").asText(""))));
        return out;
    }

    /** A short text of what the picture does not show: arms, posture, a fall, a carried cup, motion. */
    static String stateText(JsonNode r) {
        List<String> parts = new ArrayList<>();
        JsonNode arms = r.path("arms");
        if (arms.isObject()) {
            parts.add("arms " + arms.path("left").asText("?") + "/" + arms.path("right").asText("?"));
        }
        if (r.path("posture").isTextual()) {
            parts.add("posture " + r.path("posture").asText());
        }
        if (r.path("fallen").asBoolean(false)) {
            parts.add("fallen");
        }
        if (r.path("carrying").isTextual()) {
            parts.add("carrying " + r.path("carrying").asText());
        }
        double speed = r.path("v_mps").asDouble(0);
        if (Math.abs(speed) >= 0.01) {
            parts.add(String.format(Locale.ROOT, "moving %.2f m/s", speed));
        }
        return String.join(", ", parts);
    }

    private static void each(JsonNode object, BiConsumer<String, JsonNode> action) {
        if (!object.isObject()) {
            return;
        }
        for (Iterator<Map.Entry<String, JsonNode>> it = object.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            action.accept(e.getKey(), e.getValue());
        }
    }
}
