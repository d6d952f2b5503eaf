"""Sensors: Scout's ultrasonic ring and bumper sectors, Robovie's eye cameras.

All noise comes from ``random.Random`` seeded with a string made of the world seed, the sensor,
the step number and the ids involved, so a reading does not depend on how many other readings
were taken before it: querying the state more or less often never changes later events.
"""

from __future__ import annotations

import math
import random
from typing import TYPE_CHECKING, Any

import pymunk

from .geometry import dist, r, wrap

if TYPE_CHECKING:
    from .robots.base import Robot
    from .users import User
    from .world import World

SONAR_COUNT = 16
SONAR_MAX_M = 5.0
SONAR_NOISE_M = 0.01
BUMPER_COUNT = 6
CAMERA_FOV = math.radians(60.0)
CAMERA_RANGE_M = 3.0
CAMERA_MAX_TILT_DEG = 20.0
FACE_NOISE = 0.05


def noise_rng(world: "World", *key: Any) -> random.Random:
    """A generator for one reading, seeded by the world seed, the step and the key."""
    return random.Random(":".join(str(k) for k in (world.seed, world.steps, *key)))


def sonar(world: "World", robot: "Robot") -> list[float]:
    """16 range readings (m from the body's edge), transducer i at 22.5*i degrees from the heading."""
    rng = noise_rng(world, "sonar", robot.name)
    filt = pymunk.ShapeFilter(group=robot.group)
    x, y = robot.pos
    out = []
    for i in range(SONAR_COUNT):
        a = robot.heading + 2.0 * math.pi * i / SONAR_COUNT
        ca, sa = math.cos(a), math.sin(a)
        start = (x + ca * robot.radius, y + sa * robot.radius)
        end = (start[0] + ca * SONAR_MAX_M, start[1] + sa * SONAR_MAX_M)
        hit = world.space.segment_query_first(start, end, 0.0, filt)
        d = SONAR_MAX_M if hit is None else hit.alpha * SONAR_MAX_M
        d = min(SONAR_MAX_M, max(0.0, d + rng.gauss(0.0, SONAR_NOISE_M)))
        out.append(r(d, 3))
    return out


def bumper_sector(angle: float) -> int:
    """Bumper index for a contact angle relative to the heading: 0 front, counter-clockwise, 60 degrees each."""
    a = wrap(angle + math.pi / BUMPER_COUNT) % (2.0 * math.pi)
    return int(a // (2.0 * math.pi / BUMPER_COUNT)) % BUMPER_COUNT


def face_view(world: "World", robot: "Robot", user: "User", pan_deg: float, tilt_deg: float) -> dict[str, Any] | None:
    """Where a user's face is in the robot's eye cameras, or None when it is not visible.

    Visible: within range, within the horizontal field of view around heading + head pan, the
    head not tilted too far, and the line of sight (a ray cast) reaches that user first.
    """
    if abs(tilt_deg) > CAMERA_MAX_TILT_DEG:
        return None
    d = dist(robot.pos, user.pos)
    if d > CAMERA_RANGE_M:
        return None
    bearing = wrap(math.atan2(user.pos[1] - robot.pos[1], user.pos[0] - robot.pos[0]) - robot.heading)
    if abs(wrap(bearing - math.radians(pan_deg))) > CAMERA_FOV / 2.0:
        return None
    hit = world.space.segment_query_first(robot.pos, user.pos, 0.0, pymunk.ShapeFilter(group=robot.group))
    if hit is None or hit.shape is not user.shape:
        return None
    facing = abs(wrap(user.body.angle - math.atan2(robot.pos[1] - user.pos[1], robot.pos[0] - user.pos[0])))
    if facing > math.radians(100.0):
        return None  # the user shows the back of the head
    rng = noise_rng(world, "face", robot.name, user.name)
    face = [r(f + rng.gauss(0.0, FACE_NOISE), 4) for f in user.face]
    return {"bearing_deg": r(math.degrees(bearing), 2), "distance_m": r(d, 3), "face": face}
