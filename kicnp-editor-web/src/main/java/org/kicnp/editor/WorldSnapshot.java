package org.kicnp.editor;

import static java.util.Objects.requireNonNull;

import java.util.List;

/**
 * The room at one moment, as the editor draws it: one record per thing the simulator's {@code state} event
 * reports (robots, users, cups, obstacles) plus the fixed room layout from its {@code hello} (size, door,
 * counter). Metres and degrees, {@code (0, 0)} at the south-west corner, headings counter-clockwise from east.
 * Serialised to the page as it is ({@code GET /api/world}, {@code world} events).
 *
 * @param time simulated time in seconds (the event's {@code t})
 */
public record WorldSnapshot(double time, Room room, List<Robot> robots, List<User> users, List<Cup> cups,
        List<Obstacle> obstacles) {

    public WorldSnapshot {
        requireNonNull(room, "room");
        robots = List.copyOf(robots);
        users = List.copyOf(users);
        cups = List.copyOf(cups);
        obstacles = List.copyOf(obstacles);
    }

    /** The room: its size, the door in a wall and the kitchen counter (an axis-aligned box). */
    public record Room(double width, double height, Point door, Box counter) {
        /** The simulator's room: 8 m x 6 m, door at (4, 0), counter x 7.2..7.95, y 3.4..5.6. */
        public static final Room SIMULATOR = new Room(8.0, 6.0, new Point(4.0, 0.0), new Box(7.2, 3.4, 7.95, 5.6));

        public Room {
            requireNonNull(door, "door");
            requireNonNull(counter, "counter");
        }
    }

    /** A point in the room. */
    public record Point(double x, double y) {
    }

    /** An axis-aligned box from (x0, y0) to (x1, y1). */
    public record Box(double x0, double y0, double x1, double y1) {
    }

    /**
     * A robot: where it is, what it is doing and a short text of its other state.
     *
     * @param kind the simulator's kind ({@code humanoid}, {@code mobile}, {@code quadruped})
     * @param actions the running actions, one per busy body part (empty when idle)
     * @param state a short human-readable text of the rest of its state ({@code "arms up/wave"},
     *     {@code "posture sit"}, {@code "carrying tea-1"}); empty when there is nothing to say
     */
    public record Robot(String name, String kind, double x, double y, double headingDeg, List<RunningAction> actions,
            String state) {
        public Robot {
            requireNonNull(name, "name");
            requireNonNull(kind, "kind");
            requireNonNull(state, "state");
            actions = List.copyOf(actions);
        }
    }

    /** An action a robot is performing: the body part it holds, its id (the command id) and its name. */
    public record RunningAction(String part, String id, String action) {
        public RunningAction {
            requireNonNull(part, "part");
            requireNonNull(id, "id");
            requireNonNull(action, "action");
        }
    }

    /** A person in the room. */
    public record User(String name, double x, double y, double headingDeg) {
        public User {
            requireNonNull(name, "name");
        }
    }

    /**
     * A cup.
     *
     * @param kind {@code tea} or {@code coffee}
     * @param holder who holds it, as the simulator says ({@code robot:scout}, {@code user:alice}); empty when it
     *     stands on the counter
     */
    public record Cup(String name, String kind, double x, double y, String holder) {
        public Cup {
            requireNonNull(name, "name");
            requireNonNull(kind, "kind");
            requireNonNull(holder, "holder");
        }
    }

    /** A static box placed in the room ({@code add_obstacle}), centre (x, y), width w and height h. */
    public record Obstacle(String name, double x, double y, double w, double h) {
        public Obstacle {
            requireNonNull(name, "name");
        }
    }
}
