"""Scout's skills: picking up a cup from the counter, handing it to a user, raw wheel drive."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

from .specs import Arg
from .geometry import dist, r
from .room import COUNTER, CUP_X
from .skills import CUP_REACH_M, HAND_REACH_M, Timed, user_gap

if TYPE_CHECKING:
    from .world import World


class PickUp(Timed):
    """Pick up a cup ('tea', 'coffee' or a cup id) from the counter; needs to be near it; 1.5 s."""

    ARGS = (Arg("cup", "string", doc="'tea', 'coffee' or a cup id"),)

    def begin(self, world: "World") -> Optional[str]:
        if self.robot.carrying:
            return f"already carrying {self.robot.carrying}"
        want = self.args["cup"]
        free = [c for c in world.cups.values() if c.holder is None and want in (c.kind, c.id)]
        if not free:
            return f"no {want} cup on the counter"
        cup = min(free, key=lambda c: dist(self.robot.pos, (c.x, c.y)))
        gap = dist(self.robot.pos, (cup.x, cup.y)) - self.robot.radius
        if gap > CUP_REACH_M:
            return f"not near the counter: cup {cup.id} is {gap:.2f} m away (needs <= {CUP_REACH_M} m)"
        self.cup = cup
        return None

    def duration(self, world: "World") -> float:
        return 1.5

    def during(self, world: "World") -> Optional[str]:
        return None if self.cup.holder is None else f"cup {self.cup.id} was taken"

    def finish(self, world: "World") -> dict[str, Any]:
        self.cup.holder = f"robot:{self.robot.name}"
        self.robot.carrying = self.cup.id
        return {"cup": self.cup.id, "kind": self.cup.kind}


class PutDown(Timed):
    """Put the carried cup down on the counter, on its front edge level with the robot; needs to be near it; 1.5 s.

    Carrying no cup there is nothing to put down: the action ends at once with ``cup`` None, so a changed order can
    always "empty the gripper" without first asking whether the robot still holds the old cup.
    """

    ARGS = ()

    def begin(self, world: "World") -> Optional[str]:
        self.cup = world.cups.get(self.robot.carrying) if self.robot.carrying else None
        if self.cup is None:
            return None
        y0, y1 = COUNTER[1] + 0.1, COUNTER[3] - 0.1
        self.spot = (CUP_X, min(max(self.robot.pos[1], y0), y1))
        gap = dist(self.robot.pos, self.spot) - self.robot.radius
        if gap > CUP_REACH_M:
            return f"not near the counter: its edge is {gap:.2f} m away (needs <= {CUP_REACH_M} m)"
        return None

    def duration(self, world: "World") -> float:
        return 1.5 if self.cup is not None else 0.0

    def finish(self, world: "World") -> dict[str, Any]:
        if self.cup is None:
            return {"cup": None, "kind": None}
        self.cup.holder = None
        self.cup.x, self.cup.y = self.spot
        self.robot.carrying = None
        return {"cup": self.cup.id, "kind": self.cup.kind, "x": r(self.spot[0], 3), "y": r(self.spot[1], 3)}


class HandOver(Timed):
    """Hand the carried cup to a user within 0.6 m (body gap); 1.5 s."""

    ARGS = (Arg("user", "string"),)

    def begin(self, world: "World") -> Optional[str]:
        if not self.robot.carrying:
            return "not carrying a cup"
        gap = user_gap(world, self.robot, self.args["user"])
        if gap is None:
            return f"no user named {self.args['user']!r}"
        if gap > HAND_REACH_M:
            return f"user {self.args['user']!r} is {gap:.2f} m away (needs <= {HAND_REACH_M} m)"
        return None

    def duration(self, world: "World") -> float:
        return 1.5

    def during(self, world: "World") -> Optional[str]:
        gap = user_gap(world, self.robot, self.args["user"])
        if gap is None:
            return f"user {self.args['user']!r} left"
        if gap > HAND_REACH_M + 0.2:
            return f"user {self.args['user']!r} walked away"
        return None

    def finish(self, world: "World") -> dict[str, Any]:
        cup = world.cups[self.robot.carrying]
        cup.holder = f"user:{self.args['user']}"
        world.users[self.args["user"]].holding.append(cup.id)
        self.robot.carrying = None
        return {"cup": cup.id, "kind": cup.kind, "user": self.args["user"]}


class Drive(Timed):
    """Scout: run the wheels at left/right speeds (m/s) for duration_s; a bumper hit stops it."""

    ARGS = (
        Arg("left_mps", "number", lo=-0.6, hi=0.6),
        Arg("right_mps", "number", lo=-0.6, hi=0.6),
        Arg("duration_s", "number", lo=0.0, hi=600.0),
    )

    def duration(self, world: "World") -> float:
        return float(self.args["duration_s"])

    def control(self, world: "World", dt: float) -> None:
        self.robot.wheel_cmd = (float(self.args["left_mps"]), float(self.args["right_mps"]))

    def stop(self, world: "World") -> None:
        self.robot.wheel_cmd = None

    def finish(self, world: "World") -> dict[str, Any]:
        x, y = self.robot.pos
        return {"x": r(x, 3), "y": r(y, 3)}
