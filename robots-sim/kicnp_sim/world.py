"""The world: the room, users, cups and robots in one pymunk space, stepped at a fixed dt.

Everything that happens is reported as an event dict appended to ``events`` (drained by the
protocol layer). The world never reads the wall clock: its time is ``steps * dt``, and all
randomness comes from the seed, so the same seed and the same requests at the same steps give
the same events.
"""

from __future__ import annotations

import math
from typing import Any, Optional

import pymunk

from .actions import Action, Outcome
from .geometry import dist, r
from .robots import ROBOT_CLASSES, Robot
from .room import CAT_STATIC, Cup, add_obstacle, build_room
from .users import User, face_from_seed, normalise

DEFAULT_DT = 1.0 / 60.0
USER_STOP_GAP_M = 0.01  # a walking user stops this far from a robot in the way
ROBOT_STOP_GAP_M = 0.01  # a driving robot stops this far from another driving robot in the way
ROBOT_STOP_COS = math.cos(math.radians(45.0))  # "in the way": within 45 degrees of the direction it drives
START_POSES = {  # name: (x, y, heading in degrees)
    "robovie": (4.0, 3.2, -90.0),
    "pino": (2.5, 3.8, -90.0),
    "scout": (6.2, 2.0, 90.0),
    "aibo": (2.5, 2.0, 0.0),
}


class BusyError(Exception):
    """A command wants a body part that a running action holds."""


class World:
    """The simulated room and everything in it."""

    def __init__(self, seed: int = 0, dt: float = DEFAULT_DT, audio: Any = None):
        self.seed = seed
        self.dt = dt
        self.steps = 0
        self.audio = audio
        self.events: list[dict[str, Any]] = []
        self.space = pymunk.Space()
        self.space.iterations = 20
        self.cups: dict[str, Cup] = {c.id: c for c in build_room(self.space)}
        self.users: dict[str, User] = {}
        self.obstacles: dict[str, dict[str, float]] = {}
        self.robots: dict[str, Robot] = {}
        for group, (name, cls) in enumerate(ROBOT_CLASSES.items(), start=1):
            x, y, h = START_POSES[name]
            self.robots[name] = cls(self.space, name, x, y, math.radians(h), group)
        self.stream_every: Optional[int] = None
        self.stream_next = 0

    @property
    def t(self) -> float:
        return r(self.steps * self.dt, 4)

    # ---- events -------------------------------------------------------------------------
    def emit(self, type_: str, **fields: Any) -> None:
        self.events.append({"type": type_, "t": self.t, **fields})

    def sensor(self, robot: str, kind: str, data: dict[str, Any]) -> None:
        self.emit("sensor", robot=robot, sensor=kind, **data)

    def drain(self) -> list[dict[str, Any]]:
        out, self.events = self.events, []
        return out

    # ---- actions ------------------------------------------------------------------------
    def check_free(self, robot: Robot, parts: tuple[str, ...]) -> None:
        for part in parts:
            if part in robot.actions:
                a = robot.actions[part]
                raise BusyError(f"{robot.name} {part} is busy with {a.name} {a.id!r}")

    def start(self, robot: Robot, action: Action) -> None:
        """Claim the action's parts, announce it, and fail it at once if preconditions fail."""
        self.check_free(robot, action.parts)
        for part in action.parts:
            robot.actions[part] = action
        action.start_step = self.steps
        self.emit("action_started", id=action.id, robot=robot.name, action=action.name, args=action.args)
        reason = action.start(self)
        if reason:
            self.finish(action, ("failed", reason))

    def finish(self, action: Action, outcome: Outcome) -> None:
        """End or fail a running action (once), free its parts and report it."""
        robot = action.robot
        if not any(a is action for a in robot.actions.values()):
            return
        for part in action.parts:
            robot.actions.pop(part, None)
        action.stop(self)
        kind, detail = outcome
        if kind == "ended":
            self.emit("action_ended", id=action.id, robot=robot.name, action=action.name, result=detail)
        else:
            self.emit("action_failed", id=action.id, robot=robot.name, action=action.name, reason=detail)

    def busy(self) -> bool:
        return any(r.actions for r in self.robots.values()) or any(u.target for u in self.users.values())

    # ---- stepping -----------------------------------------------------------------------
    def step(self) -> None:
        """Advance the world by one dt: control, physics, sensing, action checks, streaming."""
        for robot in self.robots.values():
            robot.cmd_v = robot.cmd_w = 0.0
            for action in robot.running():
                action.control(self, self.dt)
        # Decided on every robot's command before any is changed, so two robots closing in on each other both hold.
        held = [robot for robot in self.robots.values() if self._drive_blocked(robot)]
        for robot in held:
            robot.cmd_v = 0.0  # it may still turn on the spot
        for robot in self.robots.values():
            robot.brake(robot.cmd_v == 0.0 and robot.cmd_w == 0.0)
        for user in self.users.values():
            user.update(self.dt)
            if user.target is not None and self._walk_blocked(user):
                user.stop()
        self.space.step(self.dt)
        self.steps += 1
        for cup in self.cups.values():
            self._follow(cup)
        for robot in self.robots.values():
            robot.sense(self)
        for robot in self.robots.values():
            for action in robot.running():
                if robot.actions.get(action.parts[0]) is not action:
                    continue  # already finished this step
                outcome = action.check(self)
                self._progress(action, outcome)
                if outcome is None and action.elapsed(self) > action.timeout():
                    outcome = ("failed", f"timeout after {action.timeout():g} s")
                if outcome is not None:
                    self.finish(action, outcome)
        if self.stream_every and self.steps >= self.stream_next:
            self.stream_next = self.steps + self.stream_every
            self.emit("state", **self.state())

    def _walk_blocked(self, user: User) -> bool:
        """Whether this step's walk would bring the user into a robot (a user is kinematic: it would shove the
        robot however hard it takes, even through a wall) or into the counter or an obstacle (it would walk through
        them), so the user stops in front of it instead."""
        vx, vy = user.body.velocity
        nxt = (user.pos[0] + vx * self.dt, user.pos[1] + vy * self.dt)
        radius = user.shape.radius
        if self.static_overlap(*nxt, radius) and not self.static_overlap(*user.pos, radius):
            return True
        for robot in self.robots.values():
            reach = user.shape.radius + robot.radius + USER_STOP_GAP_M
            d_next = dist(nxt, robot.pos)
            if d_next < reach and d_next < dist(user.pos, robot.pos):
                return True
        return False

    def _drive_blocked(self, robot: Robot) -> bool:
        """Whether this step's drive would bring the robot within reach of another robot that is driving too and lies
        within 45 degrees of its way: then it holds (as a robot's range sensors stop it short of a moving obstacle)
        and its stall check decides. Two driving bodies meeting in the contact solver would shove each other, the
        heavier the lighter, and the one pushed back would report 'blocked' while the other reached its goal through
        it. A robot standing still is braked instead, and one driving into it is stopped by its bumper, stall check or
        stumble."""
        v, _ = robot.drive()
        if v == 0.0:
            return False
        x, y = robot.pos
        ux, uy = math.cos(robot.heading), math.sin(robot.heading)
        if v < 0.0:
            ux, uy = -ux, -uy
        nxt = (x + ux * abs(v) * self.dt, y + uy * abs(v) * self.dt)
        for other in self.robots.values():
            if other is robot or (other.cmd_v == 0.0 and other.cmd_w == 0.0):
                continue
            d_next = dist(nxt, other.pos)
            if d_next >= robot.radius + other.radius + ROBOT_STOP_GAP_M:
                continue
            ox, oy = other.pos[0] - x, other.pos[1] - y
            d = math.hypot(ox, oy)
            if d == 0.0 or (ox * ux + oy * uy) / d > ROBOT_STOP_COS:
                return True  # the other lies ahead: a robot alongside it may still slide away
        return False

    def _progress(self, action: Action, outcome: Optional[Outcome]) -> None:
        if outcome is None and action.progress_s:
            every = max(1, round(action.progress_s / self.dt))
            if (self.steps - action.start_step) % every == 0:
                self.emit("action_progress", id=action.id, robot=action.robot.name, action=action.name,
                          elapsed_s=r(action.elapsed(self), 3), **action.progress_info(self))

    def _follow(self, cup: Cup) -> None:
        if cup.holder is None:
            return
        kind, name = cup.holder.split(":", 1)
        holder = self.robots.get(name) if kind == "robot" else self.users.get(name)
        if holder is not None:
            cup.x, cup.y = holder.pos

    def set_stream(self, period_s: Optional[float]) -> None:
        """Stream the state every period_s of simulated time (None stops it)."""
        self.stream_every = None if period_s is None else max(1, round(period_s / self.dt))
        self.stream_next = self.steps + (self.stream_every or 0)

    # ---- people and things --------------------------------------------------------------
    def spawn_user(self, name: str, x: float, y: float, heading: float, face: Optional[list[float]]) -> User:
        vec = normalise(face) if face is not None else face_from_seed(self.seed, name)
        user = User(self.space, name, x, y, heading, vec)
        self.users[name] = user
        return user

    def remove_user(self, name: str) -> None:
        user = self.users.pop(name)
        for cup_id in user.holding:
            del self.cups[cup_id]  # the cup leaves with the user
        self.space.remove(user.body, user.shape)

    def place_robot(self, robot: Robot, x: float, y: float, heading: float) -> None:
        robot.body.position = (x, y)
        robot.body.angle = heading
        robot.body.velocity = (0.0, 0.0)
        self.space.reindex_shapes_for_body(robot.body)

    def static_overlap(self, x: float, y: float, radius: float) -> Optional[str]:
        """The label of a wall, the counter or an obstacle that a circle here would overlap."""
        for info in self.space.point_query((x, y), radius, pymunk.ShapeFilter(mask=CAT_STATIC)):
            if info.distance < radius - 1e-9:
                return getattr(info.shape, "label", "something")
        return None

    def body_overlap(self, x: float, y: float, radius: float, me: Any, users: bool) -> Optional[str]:
        """The label of a robot (or, with ``users``, a user) other than the body ``me`` that a circle here would overlap."""
        bodies = [(rb.body, rb.shape) for rb in self.robots.values()]
        if users:
            bodies += [(u.body, u.shape) for u in self.users.values()]
        for body, shape in bodies:
            if body is not me and dist((x, y), body.position) < radius + shape.radius - 1e-9:
                return shape.label
        return None

    def box_overlap(self, x: float, y: float, w: float, h: float) -> Optional[str]:
        """The label of a robot or a user that a box centred here would overlap."""
        for shape in [rb.shape for rb in self.robots.values()] + [u.shape for u in self.users.values()]:
            cx, cy = shape.body.position
            nearest = (min(max(cx, x - w / 2), x + w / 2), min(max(cy, y - h / 2), y + h / 2))
            if dist(nearest, (cx, cy)) < shape.radius - 1e-9:
                return shape.label
        return None

    def add_obstacle(self, name: str, x: float, y: float, w: float, h: float) -> None:
        add_obstacle(self.space, name, x, y, w, h)
        self.obstacles[name] = {"x": x, "y": y, "w": w, "h": h}

    def state(self) -> dict[str, Any]:
        return {
            "robots": {n: rb.state(self) for n, rb in self.robots.items()},
            "users": {n: u.state() for n, u in self.users.items()},
            "cups": {c.id: c.state() for c in self.cups.values()},
            "obstacles": dict(self.obstacles),
        }
