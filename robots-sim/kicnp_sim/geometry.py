"""Small geometry and number helpers shared by the world, robots and sensors.

Angles are radians inside the simulator and degrees on the wire; every float that goes on the
wire is rounded here so that event streams are stable and byte-comparable.
"""

from __future__ import annotations

import math


def wrap(a: float) -> float:
    """Angle wrapped to [-pi, pi)."""
    return (a + math.pi) % (2.0 * math.pi) - math.pi


def clamp(x: float, lo: float, hi: float) -> float:
    """x limited to [lo, hi]."""
    return lo if x < lo else hi if x > hi else x


def r(x: float, nd: int = 4) -> float:
    """x rounded for the wire (and -0.0 turned into 0.0)."""
    return round(float(x), nd) + 0.0


def to_deg(a: float) -> float:
    """Radians -> wrapped degrees, rounded for the wire."""
    return r(math.degrees(wrap(a)), 2)


def from_deg(d: float) -> float:
    """Degrees -> wrapped radians."""
    return wrap(math.radians(d))


def dist(a: tuple[float, float], b: tuple[float, float]) -> float:
    """Euclidean distance between two points."""
    return math.hypot(a[0] - b[0], a[1] - b[1])
