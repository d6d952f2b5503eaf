"""The robot base class: a pymunk body driven by commanded speeds, body parts, actions.

Each robot is a dynamic circle with an infinite moment of inertia (collisions never spin it).
Actions set ``cmd_v`` (forward m/s) and ``cmd_w`` (turn rad/s) before each step; the body's
velocity function applies them inside the physics step, so the contact solver can still stop
the body at walls and obstacles (setting the velocity from outside the step would tunnel).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Optional

import pymunk

from ..actions import Action, ApproachUser, GoTo, Motion, TurnTo
from ..specs import ActionSpec
from ..geometry import clamp, r, to_deg
from ..room import CAT_ROBOT

if TYPE_CHECKING:
    from ..world import World


def spec(name: str, parts: tuple[str, ...], cls: type, doc: str = "") -> ActionSpec:
    """An ActionSpec whose args are the class's ARGS and whose doc is its docstring."""
    return ActionSpec(name, parts, cls, tuple(cls.ARGS), doc or (cls.__doc__ or "").strip())


MOTION_SPECS = {
    "go_to": spec("go_to", ("base",), GoTo),
    "turn_to": spec("turn_to", ("base",), TurnTo),
    "approach_user": spec("approach_user", ("base",), ApproachUser),
}


BRAKED_MASS_KG = 1.0e6
"""The mass the contact solver gives a robot whose wheels (or legs) stand still, some 25,000 times the heaviest
robot's: braked, it holds its place when another robot drives into it, and the driver is the one stopped (its
bumper, its stall check or its stumble)."""


class Robot:
    """One robot: body, limits, parts, running actions, and its state for the wire."""

    KIND = "robot"
    DESCRIPTION = ""
    RADIUS = 0.2
    MASS = 30.0
    MAX_V = 0.5
    MAX_W = 1.5
    PARTS: tuple[str, ...] = ("base",)
    ACTIONS: dict[str, ActionSpec] = {}

    def __init__(self, space: pymunk.Space, name: str, x: float, y: float, heading: float, group: int):
        self.name = name
        self.group = group
        self.radius = self.RADIUS
        self.max_v = self.MAX_V
        self.max_w = self.MAX_W
        self.cmd_v = 0.0
        self.cmd_w = 0.0
        self.v = 0.0
        self.w = 0.0
        self.actions: dict[str, Action] = {}
        self.braked = False
        self.body = pymunk.Body(self.MASS, float("inf"))
        self.body.position = (x, y)
        self.body.angle = heading
        self.body.velocity_func = self._velocity_func
        self.shape = pymunk.Circle(self.body, self.RADIUS)
        self.shape.label = f"robot:{name}"
        self.shape.friction = 0.3
        self.shape.filter = pymunk.ShapeFilter(group=group, categories=CAT_ROBOT)
        space.add(self.body, self.shape)

    @property
    def pos(self) -> tuple[float, float]:
        return (self.body.position.x, self.body.position.y)

    @property
    def heading(self) -> float:
        return self.body.angle

    def drive(self) -> tuple[float, float]:
        """(v, w) for this step from the commanded speeds, within the robot's limits."""
        return clamp(self.cmd_v, -self.max_v, self.max_v), clamp(self.cmd_w, -self.max_w, self.max_w)

    def _velocity_func(self, body: pymunk.Body, gravity: Any, damping: float, dt: float) -> None:
        self.v, self.w = self.drive()
        a = body.angle
        body.velocity = (self.v * math.cos(a), self.v * math.sin(a))
        body.angular_velocity = self.w

    def brake(self, on: bool) -> None:
        """Brakes on while the robot is commanded to stand still, off while it drives: a robot at rest is not
        shoved along by another that drives into it (the velocity function leaves no one any limit on force, so
        two bodies of their real masses would split the contact and the standing one would be pushed away)."""
        if on != self.braked:
            self.braked = on
            self.body.mass = BRAKED_MASS_KG if on else self.MASS

    def halt(self) -> None:
        """Stop at once (e.g. on a bumper hit): zero speeds now, not at the next step."""
        self.cmd_v = self.cmd_w = self.v = self.w = 0.0
        self.body.velocity = (0.0, 0.0)
        self.body.angular_velocity = 0.0

    def begin_motion(self) -> Optional[str]:
        """Called when a locomotion action starts: None when it may go, else the reason it may not."""
        return None

    def running(self) -> list[Action]:
        """The running actions, each once, in the order of the parts they hold."""
        return list(dict.fromkeys(self.actions.values()))

    def base_motion(self) -> Optional[Action]:
        """The running action that holds the base, if any."""
        return self.actions.get("base")

    def walking(self) -> bool:
        return isinstance(self.actions.get("base"), Motion)

    def contacts(self) -> list[tuple[str, float]]:
        """Current contacts: (label of the other shape, contact angle relative to the heading)."""
        found: list[tuple[str, float]] = []
        x, y = self.pos

        def visit(arb: pymunk.Arbiter) -> None:
            other = next((s for s in arb.shapes if s is not self.shape), arb.shapes[1])
            for p in arb.contact_point_set.points:
                px, py = p.point_a if arb.shapes[0] is self.shape else p.point_b
                found.append((getattr(other, "label", "?"), math.atan2(py - y, px - x) - self.heading))

        self.body.each_arbiter(visit)
        return found

    def sense(self, world: "World") -> None:
        """Robot-specific sensing after each physics step (bumpers, cameras, stumbling)."""

    def extra_state(self, world: "World") -> dict[str, Any]:
        return {}

    def state(self, world: "World") -> dict[str, Any]:
        x, y = self.pos
        return {
            "kind": self.KIND,
            "x": r(x, 3),
            "y": r(y, 3),
            "heading_deg": to_deg(self.heading),
            "v_mps": r(self.v, 3),
            "w_dps": r(math.degrees(self.w), 2),
            "actions": {part: {"id": a.id, "action": a.name} for part, a in self.actions.items()},
            **self.extra_state(world),
        }

    @classmethod
    def capabilities(cls) -> dict[str, Any]:
        return {
            "kind": cls.KIND,
            "description": cls.DESCRIPTION,
            "radius_m": cls.RADIUS,
            "max_speed_mps": cls.MAX_V,
            "max_turn_dps": round(math.degrees(cls.MAX_W), 1),
            "parts": list(cls.PARTS),
            "actions": {name: s.describe() for name, s in cls.ACTIONS.items()},
        }
