"""AIBO (ESP-220): a four-legged robot dog; walks (0.3 m/s) when standing, sits, lies down,
and has 19 lights that express emotions."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

from ..skills_aibo import N_LIGHTS, LieDown, SetLights, SetPosture
from .base import MOTION_SPECS, Robot, spec

if TYPE_CHECKING:
    from ..world import World


class Aibo(Robot):
    KIND = "quadruped"
    DESCRIPTION = "four-legged entertainment robot: walking, postures, 19 lights that express emotions"
    RADIUS = 0.15
    MASS = 1.6
    MAX_V = 0.3
    MAX_W = 1.0
    PARTS = ("base", "lights")
    ACTIONS = {
        **MOTION_SPECS,
        "set_posture": spec("set_posture", ("base",), SetPosture),
        "lie_down": spec("lie_down", ("base",), LieDown),
        "set_lights": spec("set_lights", ("lights",), SetLights),
    }

    def __init__(self, *a: Any, **kw: Any):
        super().__init__(*a, **kw)
        self.posture = "stand"
        self.posture_target: Optional[str] = None
        self.lights = ["off"] * N_LIGHTS

    def begin_motion(self) -> Optional[str]:
        return None if self.posture == "stand" else f"posture is {self.posture}: set_posture stand first"

    def extra_state(self, world: "World") -> dict[str, Any]:
        return {"posture": self.posture, "posture_target": self.posture_target, "lights": list(self.lights)}
