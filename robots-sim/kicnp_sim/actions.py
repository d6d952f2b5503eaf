"""Actions: the things a robot is told to do, which take simulated time and end by physics.

An action is created from a validated command, claims one or more body parts of its robot
("base", "arms", "head", "speech", "gripper", "lights"), is started, then each physics step
it may command the robot (``control``, before the step) and is checked (``check``, after the
step). ``check`` returns an outcome: ("ended", result) or ("failed", reason), or None while it
is still running. The world also fails an action that runs past its timeout.

This module holds the Action base and the motion actions shared by all robots (go_to,
turn_to, approach_user); timed skills live in skills.py.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Optional

from .geometry import clamp, dist, from_deg, r, to_deg, wrap
from .room import ROOM_H, ROOM_W
from .specs import Arg

if TYPE_CHECKING:
    from .robots.base import Robot
    from .world import World

Outcome = tuple[str, Any]
DEFAULT_TIMEOUT_S = 120.0
ARRIVAL_TOLERANCE_M = 0.1
HEADING_TOLERANCE = math.radians(2.0)
STALL_S = 3.0
STALL_EPS = 0.01
ARRIVE_FRACTION = 0.5


class Action:
    """Base class: an action with an id, an owner robot, its parts and its timeout."""

    def __init__(self, robot: "Robot", args: dict[str, Any]):
        self.robot = robot
        self.args = args
        self.id = ""
        self.name = ""
        self.parts: tuple[str, ...] = ()
        self.timeout_s: Optional[float] = None  # None: default_timeout()
        self.progress_s: Optional[float] = None  # emit action_progress this often (sim s)
        self.start_step = 0

    def elapsed(self, world: "World") -> float:
        return (world.steps - self.start_step) * world.dt

    def start(self, world: "World") -> Optional[str]:
        """Check preconditions; a returned string is the failure reason."""
        return None

    def timeout(self) -> float:
        """The command's timeout_s, or the default."""
        return self.timeout_s if self.timeout_s is not None else self.default_timeout()

    def default_timeout(self) -> float:
        return DEFAULT_TIMEOUT_S

    def control(self, world: "World", dt: float) -> None:
        """Command the robot for the coming physics step."""

    def check(self, world: "World") -> Optional[Outcome]:
        """After a physics step: finished, failed, or still running (None)."""
        return None

    def stop(self, world: "World") -> None:
        """Called once when the action ends or fails, to leave the robot still."""

    def progress_info(self, world: "World") -> dict[str, Any]:
        """What an action_progress event reports besides the elapsed time."""
        return {}


class Progress:
    """Detects 'no progress': the metric did not improve by eps for stall_s seconds."""

    def __init__(self, stall_s: float):
        self.stall_s = stall_s
        self.best = math.inf
        self.best_t = 0.0

    def stalled(self, t: float, metric: float) -> bool:
        if metric < self.best - STALL_EPS:
            self.best, self.best_t = metric, t
            return False
        return t - self.best_t > self.stall_s


def steer(robot: "Robot", goal: tuple[float, float]) -> tuple[float, float, float]:
    """(v, w, heading error) that drive the robot to the goal: turn in place, then go."""
    x, y = robot.pos
    d = dist((x, y), goal)
    err = wrap(math.atan2(goal[1] - y, goal[0] - x) - robot.heading)
    w = clamp(3.0 * err, -robot.max_w, robot.max_w)
    if abs(err) > 0.6:
        return 0.0, w, err
    v = max(0.08, min(robot.max_v, 1.5 * d)) * max(0.0, math.cos(err))
    return min(v, robot.max_v), w, err


def turn_rate(robot: "Robot", err: float) -> float:
    """Angular speed that closes a heading error without crawling at the end."""
    w = clamp(3.0 * err, -robot.max_w, robot.max_w)
    if abs(w) < 0.15:
        w = math.copysign(0.15, err)
    return w


MOTION_ARGS = (
    Arg("tolerance_m", "number", False, ARRIVAL_TOLERANCE_M, lo=0.01, hi=2.0, doc="arrival tolerance"),
    Arg("stall_s", "number", False, STALL_S, lo=0.1, hi=600.0, doc="fail 'blocked' after this long without progress"),
)


class Motion(Action):
    """Shared parts of the locomotion actions: walk permission, stall detection, stopping."""

    def start(self, world: "World") -> Optional[str]:
        self.progress = Progress(self.args["stall_s"])
        return self.robot.begin_motion()

    def stop(self, world: "World") -> None:
        self.robot.cmd_v = self.robot.cmd_w = 0.0

    def at_goal(self, world: "World", d: float, metric: float) -> Optional[bool]:
        """True when arrived, None while under way, False when blocked.

        The robot aims for half the tolerance (so it arrives well inside it), but a robot that
        stalls within the tolerance (say, near a wall) has arrived all the same.
        """
        tol = self.args["tolerance_m"]
        if d <= tol * ARRIVE_FRACTION:
            return True
        if self.progress.stalled(world.t, metric):
            return d <= tol
        return None

    def blocked(self, world: "World", metric: float) -> Optional[Outcome]:
        if self.progress.stalled(world.t, metric):
            return ("failed", f"blocked: no progress for {self.args['stall_s']:g} s")
        return None

    def pose_result(self) -> dict[str, Any]:
        x, y = self.robot.pos
        return {"x": r(x, 3), "y": r(y, 3), "heading_deg": to_deg(self.robot.heading)}


class GoTo(Motion):
    """Go to (x, y), optionally turning to heading_deg on arrival."""

    ARGS = (
        Arg("x", "number", lo=0.0, hi=ROOM_W),
        Arg("y", "number", lo=0.0, hi=ROOM_H),
        Arg("heading_deg", "number", False, lo=-360.0, hi=360.0),
    ) + MOTION_ARGS

    def progress_info(self, world: "World") -> dict[str, Any]:
        return {**self.pose_result(), "remaining_m": r(dist(self.robot.pos, self.goal), 3)}

    def start(self, world: "World") -> Optional[str]:
        self.goal = (float(self.args["x"]), float(self.args["y"]))
        self.turning = False
        return super().start(world)

    def control(self, world: "World", dt: float) -> None:
        if self.turning:
            err = wrap(from_deg(self.args["heading_deg"]) - self.robot.heading)
            self.robot.cmd_v, self.robot.cmd_w = 0.0, turn_rate(self.robot, err)
        else:
            self.robot.cmd_v, self.robot.cmd_w, _ = steer(self.robot, self.goal)

    def check(self, world: "World") -> Optional[Outcome]:
        d = dist(self.robot.pos, self.goal)
        if not self.turning:
            err = wrap(math.atan2(self.goal[1] - self.robot.pos[1], self.goal[0] - self.robot.pos[0]) - self.robot.heading)
            there = self.at_goal(world, d, d + 0.2 * abs(err))
            if there is False:
                return ("failed", f"blocked: no progress for {self.args['stall_s']:g} s")
            if there:
                world.sensor(self.robot.name, "arrival", {**self.pose_result(), "goal": {"x": r(self.goal[0], 3), "y": r(self.goal[1], 3)}})
                if self.args.get("heading_deg") is None:
                    return ("ended", {**self.pose_result(), "distance_error_m": r(d, 3)})
                self.turning = True
                self.progress = Progress(self.args["stall_s"])
            return None
        err = wrap(from_deg(self.args["heading_deg"]) - self.robot.heading)
        if abs(err) <= HEADING_TOLERANCE:
            return ("ended", {**self.pose_result(), "distance_error_m": r(d, 3)})
        return self.blocked(world, abs(err))


class TurnTo(Motion):
    """Turn in place to heading_deg."""

    ARGS = (Arg("heading_deg", "number", lo=-360.0, hi=360.0),) + MOTION_ARGS[1:]

    def control(self, world: "World", dt: float) -> None:
        err = wrap(from_deg(self.args["heading_deg"]) - self.robot.heading)
        self.robot.cmd_v, self.robot.cmd_w = 0.0, turn_rate(self.robot, err)

    def check(self, world: "World") -> Optional[Outcome]:
        err = wrap(from_deg(self.args["heading_deg"]) - self.robot.heading)
        if abs(err) <= HEADING_TOLERANCE:
            return ("ended", self.pose_result())
        return self.blocked(world, abs(err))


class ApproachUser(Motion):
    """Go to within distance_m (body edge to body edge) of a user, then face them."""

    ARGS = (
        Arg("user", "string"),
        Arg("distance_m", "number", False, 0.5, lo=0.05, hi=5.0, doc="gap between the robot's and the user's bodies"),
    ) + MOTION_ARGS

    def start(self, world: "World") -> Optional[str]:
        self.facing = False
        if self.args["user"] not in world.users:
            return f"no user named {self.args['user']!r}"
        return super().start(world)

    def _goal(self, world: "World") -> tuple[float, float]:
        user = world.users[self.args["user"]]
        ux, uy = user.pos
        x, y = self.robot.pos
        d = dist((x, y), (ux, uy)) or 1e-9
        reach = user.shape.radius + self.robot.radius + self.args["distance_m"]
        return (ux + (x - ux) / d * reach, uy + (y - uy) / d * reach)

    def progress_info(self, world: "World") -> dict[str, Any]:
        user = world.users.get(self.args["user"])
        if user is None:
            return {}
        return {**self.pose_result(), "gap_m": r(dist(self.robot.pos, user.pos) - user.shape.radius - self.robot.radius, 3)}

    def _face_err(self, world: "World") -> float:
        ux, uy = world.users[self.args["user"]].pos
        x, y = self.robot.pos
        return wrap(math.atan2(uy - y, ux - x) - self.robot.heading)

    def control(self, world: "World", dt: float) -> None:
        if self.args["user"] not in world.users:
            self.robot.cmd_v = self.robot.cmd_w = 0.0
        elif self.facing:
            self.robot.cmd_v, self.robot.cmd_w = 0.0, turn_rate(self.robot, self._face_err(world))
        else:
            self.robot.cmd_v, self.robot.cmd_w, _ = steer(self.robot, self._goal(world))

    def check(self, world: "World") -> Optional[Outcome]:
        name = self.args["user"]
        if name not in world.users:
            return ("failed", f"user {name!r} left")
        user = world.users[name]
        gap = dist(self.robot.pos, user.pos) - user.shape.radius - self.robot.radius
        d = dist(self.robot.pos, self._goal(world))
        if self.facing and gap > self.args["distance_m"] + self.args["tolerance_m"] + 0.3:
            self.facing = False  # the user walked away: follow
        if not self.facing:
            there = self.at_goal(world, d, d + 0.2 * abs(self._face_err(world)))
            if there is False:
                return ("failed", f"blocked: no progress for {self.args['stall_s']:g} s")
            if there:
                self.facing = True
                self.progress = Progress(self.args["stall_s"])
            return None
        err = self._face_err(world)
        if abs(err) <= math.radians(3.0):
            world.sensor(self.robot.name, "arrival", {**self.pose_result(), "user": name, "gap_m": r(gap, 3)})
            return ("ended", {**self.pose_result(), "user": name, "gap_m": r(gap, 3)})
        return self.blocked(world, abs(err))
