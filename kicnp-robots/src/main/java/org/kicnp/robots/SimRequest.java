package org.kicnp.robots;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

/**
 * One request to the simulator (a line of its stdin, see {@code robots-sim/PROTOCOL.md}), without its id:
 * {@link SimWorld} gives each request a fresh id when it sends it. A closed set, encoded by {@link SimCodec}.
 */
public sealed interface SimRequest {

    /** The protocol's {@code type} member of this request. */
    String type();

    /**
     * Runs {@code action} on {@code robot}. Argument values are strings, numbers, booleans or lists of them (the
     * simulator's argument types; it validates each against its own specs).
     * {@code progressS} asks for {@code action_progress} events at that period.
     */
    record Command(String robot, String action, Map<String, Object> args, Optional<Double> timeoutS,
                   Optional<Double> progressS) implements SimRequest {
        public Command {
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(action, "action");
            args = Map.copyOf(args);
            args.forEach((name, value) -> {
                if (!jsonScalarOrList(value)) {
                    throw new IllegalArgumentException("Argument '" + name + "' of " + robot + "." + action
                            + " is a " + value.getClass().getSimpleName() + ", not a string, number, boolean or list.");
                }
            });
            Objects.requireNonNull(timeoutS, "timeoutS");
            Objects.requireNonNull(progressS, "progressS");
        }

        private static boolean jsonScalarOrList(Object v) {
            return v instanceof String || v instanceof Number || v instanceof Boolean
                    || v instanceof List<?> l && l.stream().allMatch(Command::jsonScalarOrList);
        }

        /** A command with the simulator's default timeout and no progress events. */
        public static Command of(String robot, String action, Map<String, Object> args) {
            return new Command(robot, action, args, Optional.empty(), Optional.empty());
        }

        @Override public String type() {
            return "command";
        }
    }

    /** Puts a user in the room at (x, y) facing {@code headingDeg}; a given face replaces the seeded one. */
    record SpawnUser(String name, double x, double y, double headingDeg, Optional<List<Double>> face)
            implements SimRequest {
        public SpawnUser {
            Objects.requireNonNull(name, "name");
            face = face.map(List::copyOf);
        }

        @Override public String type() {
            return "spawn_user";
        }
    }

    /** Moves a user, walking at {@code speed} m/s or teleporting when it is absent. */
    record MoveUser(String name, double x, double y, Optional<Double> headingDeg, Optional<Double> speed)
            implements SimRequest {
        public MoveUser {
            Objects.requireNonNull(name, "name");
            Objects.requireNonNull(headingDeg, "headingDeg");
            Objects.requireNonNull(speed, "speed");
        }

        @Override public String type() {
            return "move_user";
        }
    }

    /** Takes a user out of the room. */
    record RemoveUser(String name) implements SimRequest {
        public RemoveUser {
            Objects.requireNonNull(name, "name");
        }

        @Override public String type() {
            return "remove_user";
        }
    }

    /** Teleports an idle robot. */
    record PlaceRobot(String robot, double x, double y, double headingDeg) implements SimRequest {
        public PlaceRobot {
            Objects.requireNonNull(robot, "robot");
        }

        @Override public String type() {
            return "place_robot";
        }
    }

    /** Adds a static box centred at (x, y), {@code w} by {@code h} metres. */
    record AddObstacle(String name, double x, double y, double w, double h) implements SimRequest {
        public AddObstacle {
            Objects.requireNonNull(name, "name");
        }

        @Override public String type() {
            return "add_obstacle";
        }
    }

    /** Cancels a running action of a robot. */
    record Cancel(String robot, String actionId) implements SimRequest {
        public Cancel {
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(actionId, "actionId");
        }

        @Override public String type() {
            return "cancel";
        }
    }

    /** Asks for the whole state; a {@link SimEvent.State} with the same id follows the ack. */
    record Query() implements SimRequest {
        @Override public String type() {
            return "query";
        }
    }

    /** Turns the periodic state stream on or off. */
    record Stream(boolean enabled, int periodMs) implements SimRequest {
        @Override public String type() {
            return "stream";
        }
    }

    /** Manual mode only: advances the world; the ack comes after the step's events. */
    record Step(double seconds, boolean untilIdle) implements SimRequest {
        @Override public String type() {
            return "step";
        }
    }

    /** Changes the real-time speed-up (no effect in manual mode). */
    record SetTimeScale(double timeScale) implements SimRequest {
        @Override public String type() {
            return "set_time_scale";
        }
    }

    /** Asks the simulator to exit with status 0 after its ack. */
    record Shutdown() implements SimRequest {
        @Override public String type() {
            return "shutdown";
        }
    }
}
