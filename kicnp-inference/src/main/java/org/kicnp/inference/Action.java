package org.kicnp.inference;

import static java.util.Objects.requireNonNull;

import java.util.List;

/**
 * A command for a robot, issued by a firing ({@code sendmsg} or {@code command} in a script): its id, the robot that
 * performs it, the target frame the script named (a robot, or a part such as a Mouth whose {@code robot} slot names
 * the robot), the action name and arguments, the behavior frame and instance that issued it, the time allowed for it
 * (ms), and the start time it is released with (one start time for a synchronization group; 0 until released).
 */
public record Action(String id, String robot, String target, String name, List<String> args, String frame,
                     String instance, long timeoutMillis, long startAt) {
    public Action {
        requireNonNull(id, "id");
        requireNonNull(robot, "robot");
        requireNonNull(target, "target");
        requireNonNull(name, "name");
        args = List.copyOf(args);
        requireNonNull(frame, "frame");
        requireNonNull(instance, "instance");
    }

    Action releasedAt(long time) {
        return new Action(id, robot, target, name, args, frame, instance, timeoutMillis, time);
    }

    /** An action that has not finished, and where it stands (held, sent or started). */
    public record Unfinished(Action action, Status status) {
        public Unfinished {
            requireNonNull(action, "action");
            requireNonNull(status, "status");
        }
    }

    /** Life cycle of an action. */
    public enum Status {
        /** Waiting on a coordination relation (succession, synchronization, restriction). */
        HELD,
        /** Handed to the action sink. */
        SENT,
        /** The robot reported it started. */
        STARTED,
        /** The robot reported it ended. */
        ENDED,
        /** The robot, or a predecessor, failed it. */
        FAILED,
        /** No end was reported within the timeout. */
        TIMED_OUT;

        public boolean finished() {
            return this == ENDED || this == FAILED || this == TIMED_OUT;
        }
    }
}
