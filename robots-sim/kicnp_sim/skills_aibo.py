"""AIBO's skills: posture changes (stand, sit, lie_down) and its 19 lights."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any, Optional

from .specs import Arg
from .skills import Timed

if TYPE_CHECKING:
    from .world import World

POSTURES = ("stand", "sit", "lie_down")
POSTURE_S = {
    frozenset(("stand", "sit")): 1.0,
    frozenset(("sit", "lie_down")): 1.2,
    frozenset(("stand", "lie_down")): 1.5,
}
COLOURS = ("off", "red", "green", "blue", "white", "yellow", "orange", "pink", "purple")
HEX = re.compile(r"^#[0-9a-fA-F]{6}$")
N_LIGHTS = 19


class SetPosture(Timed):
    """AIBO posture change: stand <-> sit 1.0 s, sit <-> lie_down 1.2 s, stand <-> lie_down 1.5 s."""

    ARGS = (Arg("posture", "string", choices=POSTURES),)

    def target(self) -> str:
        return self.args["posture"]

    def begin(self, world: "World") -> Optional[str]:
        self.robot.posture_target = self.target()
        return None

    def duration(self, world: "World") -> float:
        return POSTURE_S.get(frozenset((self.robot.posture, self.target())), 0.0)

    def stop(self, world: "World") -> None:
        self.robot.posture_target = None

    def finish(self, world: "World") -> dict[str, Any]:
        self.robot.posture = self.target()
        return {"posture": self.robot.posture}


class LieDown(SetPosture):
    """AIBO lies down (same as set_posture lie_down)."""

    ARGS = ()

    def target(self) -> str:
        return "lie_down"


class SetLights(Timed):
    """Set AIBO's 19 lights: 'all' to one colour, and/or 'lights' as a list of 19 or {index: colour}."""

    ARGS = (
        Arg("all", "string", False, doc="one colour for every light"),
        Arg("lights", "any", False, doc="list of 19 colours, or object {index: colour}"),
    )

    @classmethod
    def validate(cls, args: dict[str, Any]) -> Optional[tuple[str, str]]:
        def bad(c: Any) -> bool:
            return not isinstance(c, str) or not (c in COLOURS or HEX.match(c))

        if args.get("all") is None and args.get("lights") is None:
            return ("args.all", "is required (or args.lights)")
        if args.get("all") is not None and bad(args["all"]):
            return ("args.all", f"must be one of {', '.join(COLOURS)} or #rrggbb")
        lights = args.get("lights")
        if lights is None:
            return None
        if isinstance(lights, list):
            if len(lights) != N_LIGHTS:
                return ("args.lights", f"must have {N_LIGHTS} entries, got {len(lights)}")
            items = list(enumerate(lights))
        elif isinstance(lights, dict):
            items = []
            for k, v in lights.items():
                if not (k.isascii() and k.isdigit() and 0 <= int(k) < N_LIGHTS):  # '²' is a digit int() refuses
                    return (f"args.lights.{k}", f"must be a light index 0..{N_LIGHTS - 1}")
                items.append((int(k), v))
        else:
            return ("args.lights", "must be a list or an object")
        for i, c in items:
            if bad(c):
                return (f"args.lights.{i}", f"must be one of {', '.join(COLOURS)} or #rrggbb")
        return None

    def duration(self, world: "World") -> float:
        return 0.0

    def finish(self, world: "World") -> dict[str, Any]:
        lights = self.robot.lights
        if self.args.get("all") is not None:
            lights[:] = [self.args["all"]] * N_LIGHTS
        new = self.args.get("lights")
        if isinstance(new, list):
            lights[:] = list(new)
        elif isinstance(new, dict):
            for k, v in new.items():
                lights[int(k)] = v
        return {"lights": list(lights)}
