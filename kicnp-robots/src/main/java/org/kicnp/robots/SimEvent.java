package org.kicnp.robots;

import com.fasterxml.jackson.databind.JsonNode;

import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * One event from the simulator (a line of its stdout, see {@code robots-sim/PROTOCOL.md}), or {@link Exited}, which
 * {@link SimWorld} synthesises when the process dies. A closed set: handle it with an exhaustive {@code switch}.
 * Free-form payloads whose shape depends on the action ({@code result}, {@code args}, the world state) stay JSON.
 */
public sealed interface SimEvent {

    /** Simulated time of the event in seconds ({@code NaN} for {@link Exited}, which has none). */
    double t();

    /** The first line: protocol version, seed, mode and the robots with their actions. */
    record Hello(double t, String protocol, long seed, String mode, JsonNode robots) implements SimEvent {
        public Hello {
            Objects.requireNonNull(protocol, "protocol");
            Objects.requireNonNull(mode, "mode");
            Objects.requireNonNull(robots, "robots");
        }
    }

    /** A request was accepted; {@code result} is absent for requests that return nothing. */
    record Ack(double t, String id, Optional<JsonNode> result) implements SimEvent {
        public Ack {
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(result, "result");
        }
    }

    /** A request was invalid or refused; {@code id} is absent when the line had no usable id. */
    record Error(double t, Optional<String> id, Optional<String> field, String message) implements SimEvent {
        public Error {
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(field, "field");
            Objects.requireNonNull(message, "message");
        }
    }

    /** An accepted command started; {@code args} has the defaults filled in. */
    record ActionStarted(double t, String id, String robot, String action, JsonNode args) implements SimEvent {
        public ActionStarted {
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(action, "action");
            Objects.requireNonNull(args, "args");
        }
    }

    /** Periodic progress of a command sent with {@code progress_s}: the whole event, for its action-specific fields. */
    record ActionProgress(double t, String id, String robot, String action, Optional<Double> fraction, JsonNode body)
            implements SimEvent {
        public ActionProgress {
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(action, "action");
            Objects.requireNonNull(fraction, "fraction");
            Objects.requireNonNull(body, "body");
        }
    }

    /** A command ended well, with its action-specific result. */
    record ActionEnded(double t, String id, String robot, String action, JsonNode result) implements SimEvent {
        public ActionEnded {
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(action, "action");
            Objects.requireNonNull(result, "result");
        }
    }

    /** A command started and the world said no: {@code reason} is the simulator's sentence. */
    record ActionFailed(double t, String id, String robot, String action, String reason) implements SimEvent {
        public ActionFailed {
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(action, "action");
            Objects.requireNonNull(reason, "reason");
        }
    }

    /** A face came into (seen) or left (lost) Robovie's eye cameras: the noisy descriptor, never the identity. */
    record Face(double t, String robot, boolean seen, String track, double bearingDeg, double distanceM,
                List<Double> face, Optional<String> truthUser) implements SimEvent {
        public Face {
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(track, "track");
            face = List.copyOf(face);
            Objects.requireNonNull(truthUser, "truthUser");
        }
    }

    /** A bumper switch was pressed (with what it touched) or released. */
    record Bumper(double t, String robot, int bumper, boolean pressed, Optional<String> contact) implements SimEvent {
        public Bumper {
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(contact, "contact");
        }
    }

    /** A {@code go_to} or {@code approach_user} reached its goal; {@code user} is set for an approach. */
    record Arrival(double t, String robot, double x, double y, double headingDeg, Optional<String> user)
            implements SimEvent {
        public Arrival {
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(user, "user");
        }
    }

    /** PINO stumbled on something. */
    record Fall(double t, String robot, String contact) implements SimEvent {
        public Fall {
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(contact, "contact");
        }
    }

    /** A robot started speaking ({@code say}); {@code id} is the command's id. */
    record Utterance(double t, String robot, String id, String text, double durationS) implements SimEvent {
        public Utterance {
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(text, "text");
        }
    }

    /** The world's state, answering a {@code query} (with its id) or streamed (without). */
    record State(double t, Optional<String> id, JsonNode world) implements SimEvent {
        public State {
            Objects.requireNonNull(id, "id");
            Objects.requireNonNull(world, "world");
        }
    }

    /** Synthesised by {@link SimWorld}: the simulator process is gone; {@code reason} says how. */
    record Exited(String reason) implements SimEvent {
        public Exited {
            Objects.requireNonNull(reason, "reason");
        }

        @Override public double t() {
            return Double.NaN;
        }
    }
}
