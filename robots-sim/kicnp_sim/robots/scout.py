"""Scout: a differential-drive mobile robot with 16 sonars, 6 bumpers, and a cup holder.

Forward/turn commands are turned into left/right wheel speeds (limited to 0.6 m/s per wheel)
and back, so the body moves as the wheels allow. A bumper hit stops the robot at once and fails
whatever holds the base with "blocked: bumper N".
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

from .. import sensors
from ..geometry import r
from ..skills_scout import Drive, HandOver, PickUp, PutDown
from .base import MOTION_SPECS, Robot, spec

if TYPE_CHECKING:
    from ..world import World

WHEEL_BASE_M = 0.34
MAX_WHEEL_MPS = 0.6
BUMPER_RELEASE_S = 0.25


class Scout(Robot):
    KIND = "mobile"
    DESCRIPTION = "differential drive, 16 ultrasonic sensors, 6 bumper switches, carries one cup"
    RADIUS = 0.2
    MASS = 25.0
    MAX_V = 0.5
    MAX_W = 2.0
    PARTS = ("base", "gripper")
    ACTIONS = {
        **MOTION_SPECS,
        "drive": spec("drive", ("base",), Drive),
        "pick_up": spec("pick_up", ("base", "gripper"), PickUp),
        "hand_over": spec("hand_over", ("base", "gripper"), HandOver),
        "put_down": spec("put_down", ("base", "gripper"), PutDown),
    }

    def __init__(self, *a: Any, **kw: Any):
        super().__init__(*a, **kw)
        self.carrying: Optional[str] = None
        self.wheel_cmd: Optional[tuple[float, float]] = None
        self.wheels = (0.0, 0.0)
        self.pressed: dict[int, int] = {}  # bumper -> last step it was in contact
        self.touched: set[str] = set()  # what Scout touched at the last step
        self.base_seen: Any = None  # the base action when it was first sensed...
        self.exempt: set[str] = set()  # ...and what Scout touched then: it may move off (or turn along) those

    def drive(self) -> tuple[float, float]:
        if self.wheel_cmd is not None:
            left, right = self.wheel_cmd
        else:
            left = self.cmd_v - self.cmd_w * WHEEL_BASE_M / 2.0
            right = self.cmd_v + self.cmd_w * WHEEL_BASE_M / 2.0
        top = max(abs(left), abs(right))
        if top > MAX_WHEEL_MPS:
            left, right = left * MAX_WHEEL_MPS / top, right * MAX_WHEEL_MPS / top
        self.wheels = (left, right)
        return (left + right) / 2.0, (right - left) / WHEEL_BASE_M

    def halt(self) -> None:
        super().halt()
        self.wheel_cmd = None
        self.wheels = (0.0, 0.0)

    def sense(self, world: "World") -> None:
        hits: dict[int, list[str]] = {}
        for label, angle in self.contacts():
            hits.setdefault(sensors.bumper_sector(angle), []).append(label)
        base = self.actions.get("base")
        if base is not self.base_seen:
            self.base_seen, self.exempt = base, set(self.touched)
        self.touched = {label for labels in hits.values() for label in labels}
        for n in sorted(hits):
            if n not in self.pressed:
                world.sensor(self.name, "bumper", {"bumper": n, "pressed": True, "contact": hits[n][0]})
                base = self.actions.get("base")
                if base is not None and any(label not in self.exempt for label in hits[n]):
                    self.halt()
                    world.finish(base, ("failed", f"blocked: bumper {n}"))
            self.pressed[n] = world.steps
        for n in sorted(self.pressed):
            if n not in hits and (world.steps - self.pressed[n]) * world.dt > BUMPER_RELEASE_S:
                del self.pressed[n]
                world.sensor(self.name, "bumper", {"bumper": n, "pressed": False})

    def extra_state(self, world: "World") -> dict[str, Any]:
        return {
            "wheels_mps": {"left": r(self.wheels[0], 3), "right": r(self.wheels[1], 3)},
            "bumpers": [n in self.pressed for n in range(sensors.BUMPER_COUNT)],
            "sonar_m": sensors.sonar(world, self),
            "carrying": self.carrying,
        }
