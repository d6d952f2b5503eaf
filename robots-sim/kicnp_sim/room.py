"""The room of the scenario: walls, the kitchen counter with cups, the door, extra obstacles.

The room is an 8 m x 6 m rectangle with (0, 0) at the south-west corner, x to the east and y to
the north. The door is in the south wall at x = 4; users come in there. The kitchen counter
stands against the east wall; cups of tea and coffee sit on its front (west) edge.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import pymunk

from .geometry import r

ROOM_W = 8.0
ROOM_H = 6.0
WALL_RADIUS = 0.05
DOOR = (4.0, 0.0)
DOOR_ENTRY = (4.0, 0.6)  # where a user spawned without a position appears, facing north
COUNTER = (7.2, 3.4, 7.95, 5.6)  # x0, y0, x1, y1
CUP_X = 7.3
CUPS = (("tea-1", "tea", 3.7), ("tea-2", "tea", 4.0), ("coffee-1", "coffee", 4.6), ("coffee-2", "coffee", 4.9))

CAT_STATIC = 0b0001
CAT_USER = 0b0010
CAT_ROBOT = 0b0100


@dataclass
class Cup:
    """A cup on the counter, carried by a robot, or held by a user."""

    id: str
    kind: str
    x: float
    y: float
    holder: str | None = None  # None (on the counter), "robot:<name>" or "user:<name>"

    def state(self) -> dict[str, Any]:
        return {"kind": self.kind, "x": r(self.x, 3), "y": r(self.y, 3), "holder": self.holder}


def _box(space: pymunk.Space, x0: float, y0: float, x1: float, y1: float, label: str) -> pymunk.Poly:
    verts = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    shape = pymunk.Poly(space.static_body, verts)
    shape.label = label
    shape.friction = 0.3
    shape.filter = pymunk.ShapeFilter(categories=CAT_STATIC)
    space.add(shape)
    return shape


def build_room(space: pymunk.Space) -> list[Cup]:
    """Add the walls and the counter to the space; returns the cups on the counter."""
    corners = [(0.0, 0.0), (ROOM_W, 0.0), (ROOM_W, ROOM_H), (0.0, ROOM_H)]
    names = ["south wall", "east wall", "north wall", "west wall"]
    for i, name in enumerate(names):
        seg = pymunk.Segment(space.static_body, corners[i], corners[(i + 1) % 4], WALL_RADIUS)
        seg.label = name
        seg.friction = 0.3
        seg.filter = pymunk.ShapeFilter(categories=CAT_STATIC)
        space.add(seg)
    _box(space, *COUNTER, "counter")
    return [Cup(cid, kind, CUP_X, y) for cid, kind, y in CUPS]


def add_obstacle(space: pymunk.Space, name: str, x: float, y: float, w: float, h: float) -> pymunk.Poly:
    """A static box obstacle centred on (x, y) of size w x h."""
    return _box(space, x - w / 2, y - h / 2, x + w / 2, y + h / 2, name)


def describe() -> dict[str, Any]:
    """The static layout, as sent in the hello event."""
    return {
        "width": ROOM_W,
        "height": ROOM_H,
        "door": {"x": DOOR[0], "y": DOOR[1], "entry": {"x": DOOR_ENTRY[0], "y": DOOR_ENTRY[1]}},
        "counter": {"x0": COUNTER[0], "y0": COUNTER[1], "x1": COUNTER[2], "y1": COUNTER[3]},
    }
