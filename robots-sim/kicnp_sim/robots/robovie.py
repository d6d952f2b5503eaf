"""Robovie: a humanoid upper torso on a wheeled base; arms, a head with eye cameras, a speaker.

Each step the eye cameras look for faces: a user entering the view gives a face_seen sensor
event with the face descriptor plus Gaussian noise, bearing and distance; a user leaving it
gives face_lost (with the last reading).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .. import sensors
from ..skills import Head, MoveArms, Say, ShakeHands
from .base import MOTION_SPECS, Robot, spec

if TYPE_CHECKING:
    from ..world import World


class Robovie(Robot):
    KIND = "humanoid"
    DESCRIPTION = "humanoid upper torso on a wheeled base: two eye cameras, arms, head, speaker"
    RADIUS = 0.3
    MASS = 40.0
    MAX_V = 0.4
    MAX_W = 1.2
    PARTS = ("base", "arms", "head", "speech")
    ACTIONS = {
        **MOTION_SPECS,
        "move_arms": spec("move_arms", ("arms",), MoveArms),
        "head": spec("head", ("head",), Head),
        "shake_hands": spec("shake_hands", ("base", "arms"), ShakeHands, "Shake both hands with a user within 0.6 m; 2 s."),
        "say": spec("say", ("speech",), Say),
    }

    def __init__(self, *a: Any, **kw: Any):
        super().__init__(*a, **kw)
        self.arms = {"left": "down", "right": "down"}
        self.head = {"pan_deg": 0.0, "tilt_deg": 0.0}
        self.in_view: dict[str, dict[str, Any]] = {}
        self.tracks = 0

    def sense(self, world: "World") -> None:
        seen: dict[str, dict[str, Any]] = {}
        for name in sorted(world.users):
            view = sensors.face_view(world, self, world.users[name], self.head["pan_deg"], self.head["tilt_deg"])
            if view is not None:
                seen[name] = view
        for name in sorted(set(self.in_view) - set(seen)):
            last = self.in_view.pop(name)
            world.sensor(self.name, "face_lost", {**last, "truth_user": name})
        for name, view in seen.items():
            if name not in self.in_view:
                self.tracks += 1
                view["track"] = f"face-{self.tracks}"
                world.sensor(self.name, "face_seen", {**view, "truth_user": name})
            else:
                view["track"] = self.in_view[name]["track"]
            self.in_view[name] = view

    def extra_state(self, world: "World") -> dict[str, Any]:
        return {
            "arms": dict(self.arms),
            "head": dict(self.head),
            "faces_in_view": [{"track": v["track"], "truth_user": n, "bearing_deg": v["bearing_deg"],
                               "distance_m": v["distance_m"]} for n, v in sorted(self.in_view.items())],
        }
