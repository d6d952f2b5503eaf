"""Users: people in the room, with a position, a heading and a face descriptor.

A user is a kinematic pymunk body (robots bump into users, users push robots aside). A user can
be teleported or walk in a straight line to a target at a given speed.
"""

from __future__ import annotations

import math
import random
from typing import Any

import pymunk

from .geometry import dist, r, to_deg
from .room import CAT_USER

FACE_DIM = 16
USER_RADIUS = 0.25


def normalise(v: list[float]) -> list[float]:
    """v scaled to unit length (ValueError for the zero vector).

    Huge or tiny components (whose squares overflow or vanish) are scaled by the largest one first.
    """
    n = math.sqrt(sum(x * x for x in v))
    if 1e-150 < n < math.inf:
        return [x / n for x in v]
    top = max(abs(float(x)) for x in v)
    if top == 0.0:
        raise ValueError("face vector must not be all zeros")
    w = [float(x) / top for x in v]
    n = math.sqrt(sum(x * x for x in w))
    return [x / n for x in w]


def face_from_seed(seed: int, name: str) -> list[float]:
    """A deterministic unit face descriptor for a user name under a world seed."""
    rng = random.Random(f"{seed}:face:{name}")
    return normalise([rng.gauss(0.0, 1.0) for _ in range(FACE_DIM)])


class User:
    """A person in the room."""

    def __init__(self, space: pymunk.Space, name: str, x: float, y: float, heading: float, face: list[float]):
        self.name = name
        self.face = face
        self.holding: list[str] = []
        self.target: tuple[float, float] | None = None
        self.speed = 0.0
        self.body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
        self.body.position = (x, y)
        self.body.angle = heading
        self.shape = pymunk.Circle(self.body, USER_RADIUS)
        self.shape.label = f"user:{name}"
        self.shape.friction = 0.3
        self.shape.filter = pymunk.ShapeFilter(categories=CAT_USER)
        space.add(self.body, self.shape)

    @property
    def pos(self) -> tuple[float, float]:
        return (self.body.position.x, self.body.position.y)

    def walk_to(self, x: float, y: float, speed: float) -> None:
        """Start walking in a straight line to (x, y)."""
        self.target = (x, y)
        self.speed = speed

    def stop(self) -> None:
        """End the walk where the user stands."""
        self.target = None
        self.body.velocity = (0.0, 0.0)

    def update(self, dt: float) -> None:
        """Set the kinematic velocity for this step (called before the physics step)."""
        if self.target is None:
            self.body.velocity = (0.0, 0.0)
            return
        d = dist(self.pos, self.target)
        if d <= 1e-3:
            self.body.position = self.target
            self.body.velocity = (0.0, 0.0)
            self.target = None
            return
        v = min(self.speed, d / dt)
        dx, dy = (self.target[0] - self.pos[0]) / d, (self.target[1] - self.pos[1]) / d
        self.body.velocity = (dx * v, dy * v)

    def state(self) -> dict[str, Any]:
        x, y = self.pos
        return {
            "x": r(x, 3),
            "y": r(y, 3),
            "heading_deg": to_deg(self.body.angle),
            "walking": self.target is not None,
            "holding": list(self.holding),
        }
