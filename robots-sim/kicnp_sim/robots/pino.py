"""PINO: a small biped humanoid; slow stable walking, arm motion, hand shaking.

Walking is speed-limited (0.25 m/s). A collision while walking makes PINO stumble: the walk
fails with reason "stumbled" and PINO is down (``fallen``) until a stand_up action. Things
PINO already touched when the walk started do not count, so it can walk away from them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

from ..skills import MoveArms, ShakeHands, StandUp
from .base import MOTION_SPECS, Robot, spec

if TYPE_CHECKING:
    from ..world import World


class Pino(Robot):
    KIND = "humanoid"
    DESCRIPTION = "biped humanoid, 26 degrees of freedom: stable biped walking, arm motion, hand shaking"
    RADIUS = 0.18
    MASS = 8.0
    MAX_V = 0.25
    MAX_W = 0.8
    PARTS = ("base", "arms")
    ACTIONS = {
        **MOTION_SPECS,
        "move_arms": spec("move_arms", ("arms",), MoveArms),
        "shake_hands": spec("shake_hands", ("base", "arms"), ShakeHands),
        "stand_up": spec("stand_up", ("base", "arms"), StandUp),
    }

    def __init__(self, *a: Any, **kw: Any):
        super().__init__(*a, **kw)
        self.arms = {"left": "down", "right": "down"}
        self.fallen = False
        self.touching: set[str] = set()

    def begin_motion(self) -> Optional[str]:
        if self.fallen:
            return "fallen: stand_up first"
        self.touching = {label for label, _ in self.contacts()}  # walking away from these is fine
        return None

    def sense(self, world: "World") -> None:
        if not self.walking():
            return
        hit = [c for c in self.contacts() if c[0] not in self.touching]
        if hit:
            self.halt()
            self.fallen = True
            world.sensor(self.name, "fall", {"contact": hit[0][0]})
            world.finish(self.actions["base"], ("failed", "stumbled"))

    def extra_state(self, world: "World") -> dict[str, Any]:
        return {"arms": dict(self.arms), "fallen": self.fallen}
