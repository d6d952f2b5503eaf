"""Timed skills: actions that take a known time once their preconditions hold.

Speaking, arm and head motion, shaking hands, picking up and handing over a cup, AIBO's
postures and lights, Scout's raw wheel drive and PINO standing up. Each one checks its
preconditions against the world when it starts (failing with a reason when they do not hold),
may fail while running (the user walked away), and applies its effect when its time is up.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any, Optional

from .actions import Action, Arg, Outcome
from .geometry import dist, r

if TYPE_CHECKING:
    from .world import World

HAND_REACH_M = 0.6  # gap between bodies for shaking hands and handing over a cup
CUP_REACH_M = 0.4  # gap between the robot's body and a cup on the counter
SAY_S_PER_CHAR = 0.06
SAY_MIN_S = 0.5
ARM_POSES = ("down", "up", "wave", "shake")
POSTURES = ("stand", "sit", "lie_down")
POSTURE_S = {
    frozenset(("stand", "sit")): 1.0,
    frozenset(("sit", "lie_down")): 1.2,
    frozenset(("stand", "lie_down")): 1.5,
}
COLOURS = ("off", "red", "green", "blue", "white", "yellow", "orange", "pink", "purple")
HEX = re.compile(r"^#[0-9a-fA-F]{6}$")
N_LIGHTS = 19


def user_gap(world: "World", robot: Any, name: str) -> Optional[float]:
    """Gap between a robot's body and a user's body, or None when there is no such user."""
    user = world.users.get(name)
    if user is None:
        return None
    return dist(robot.pos, user.pos) - robot.radius - user.shape.radius


class Timed(Action):
    """An action that lasts a fixed time after its preconditions hold."""

    def begin(self, world: "World") -> Optional[str]:
        """Check preconditions and apply start effects; a string is the failure reason."""
        return None

    def duration(self, world: "World") -> float:
        return 1.0

    def during(self, world: "World") -> Optional[str]:
        """Checked each step while running; a string fails the action."""
        return None

    def finish(self, world: "World") -> dict[str, Any]:
        """Apply the effect; returns the result."""
        return {}

    def start(self, world: "World") -> Optional[str]:
        reason = self.begin(world)
        self.dur = self.duration(world)
        return reason

    def progress_info(self, world: "World") -> dict[str, Any]:
        return {"fraction": r(min(1.0, self.elapsed(world) / self.dur), 3) if self.dur > 0 else 1.0}

    def check(self, world: "World") -> Optional[Outcome]:
        reason = self.during(world)
        if reason:
            return ("failed", reason)
        if self.elapsed(world) >= self.dur - 1e-9:
            return ("ended", {**self.finish(world), "duration_s": r(self.dur, 3)})
        return None


class Say(Timed):
    """Speak a text: an utterance event now, ending after 0.06 s per character (min 0.5 s)."""

    ARGS = (Arg("text", "string"),)

    def duration(self, world: "World") -> float:
        return max(SAY_MIN_S, SAY_S_PER_CHAR * len(self.args["text"]))

    def start(self, world: "World") -> Optional[str]:
        super().start(world)
        extra: dict[str, Any] = {}
        audio = world.audio.speak(self.robot.name, self.id, self.args["text"]) if world.audio else None
        if audio:
            extra["audio_file"] = audio
        world.emit("utterance", robot=self.robot.name, id=self.id, text=self.args["text"],
                   duration_s=r(self.dur, 3), **extra)
        return None

    def finish(self, world: "World") -> dict[str, Any]:
        return {"text": self.args["text"]}


class MoveArms(Timed):
    """Move the arms to named poses (both with 'pose', or each with 'left'/'right'); 1 s."""

    ARGS = (
        Arg("pose", "string", False, choices=ARM_POSES, doc="both arms"),
        Arg("left", "string", False, choices=ARM_POSES),
        Arg("right", "string", False, choices=ARM_POSES),
    )

    @classmethod
    def validate(cls, args: dict[str, Any]) -> Optional[tuple[str, str]]:
        if not any(args.get(k) for k in ("pose", "left", "right")):
            return ("args.pose", "is required (or args.left / args.right)")
        return None

    def finish(self, world: "World") -> dict[str, Any]:
        arms = self.robot.arms
        for side in ("left", "right"):
            arms[side] = self.args.get(side) or self.args.get("pose") or arms[side]
        return {"arms": dict(arms)}


class Head(Timed):
    """Turn the head to pan/tilt angles at 90 degrees per second (min 0.2 s)."""

    ARGS = (
        Arg("pan_deg", "number", False, lo=-90.0, hi=90.0),
        Arg("tilt_deg", "number", False, lo=-30.0, hi=30.0),
    )

    def begin(self, world: "World") -> Optional[str]:
        h = self.robot.head
        self.start_pose = (h["pan_deg"], h["tilt_deg"])
        p = self.args.get("pan_deg")
        t = self.args.get("tilt_deg")
        self.goal = (self.start_pose[0] if p is None else float(p), self.start_pose[1] if t is None else float(t))
        return None

    def duration(self, world: "World") -> float:
        change = max(abs(self.goal[0] - self.start_pose[0]), abs(self.goal[1] - self.start_pose[1]))
        return max(0.2, change / 90.0)

    def control(self, world: "World", dt: float) -> None:
        f = min(1.0, (self.elapsed(world) + dt) / self.dur)
        for i, key in enumerate(("pan_deg", "tilt_deg")):
            self.robot.head[key] = r(self.start_pose[i] + f * (self.goal[i] - self.start_pose[i]), 3)

    def finish(self, world: "World") -> dict[str, Any]:
        self.robot.head.update(pan_deg=r(self.goal[0], 3), tilt_deg=r(self.goal[1], 3))
        return {"head": dict(self.robot.head)}


class ShakeHands(Timed):
    """Shake hands with a user within 0.6 m (body gap); takes 2 s."""

    ARGS = (Arg("user", "string"),)

    def begin(self, world: "World") -> Optional[str]:
        gap = user_gap(world, self.robot, self.args["user"])
        if gap is None:
            return f"no user named {self.args['user']!r}"
        if gap > HAND_REACH_M:
            return f"user {self.args['user']!r} is {gap:.2f} m away (needs <= {HAND_REACH_M} m)"
        self.before = dict(self.robot.arms)
        self.robot.arms.update(left="shake", right="shake")
        return None

    def duration(self, world: "World") -> float:
        return 2.0

    def during(self, world: "World") -> Optional[str]:
        gap = user_gap(world, self.robot, self.args["user"])
        if gap is None or gap > HAND_REACH_M + 0.2:
            return f"user {self.args['user']!r} walked away"
        return None

    def stop(self, world: "World") -> None:
        if hasattr(self, "before"):
            self.robot.arms.update(self.before)

    def finish(self, world: "World") -> dict[str, Any]:
        return {"user": self.args["user"]}


class PickUp(Timed):
    """Pick up a cup ('tea', 'coffee' or a cup id) from the counter; needs to be near it; 1.5 s."""

    ARGS = (Arg("cup", "string", doc="'tea', 'coffee' or a cup id"),)

    def begin(self, world: "World") -> Optional[str]:
        if self.robot.carrying:
            return f"already carrying {self.robot.carrying}"
        want = self.args["cup"]
        free = [c for c in world.cups.values() if c.holder is None and want in (c.kind, c.id)]
        if not free:
            return f"no {want} cup on the counter"
        cup = min(free, key=lambda c: dist(self.robot.pos, (c.x, c.y)))
        gap = dist(self.robot.pos, (cup.x, cup.y)) - self.robot.radius
        if gap > CUP_REACH_M:
            return f"not near the counter: cup {cup.id} is {gap:.2f} m away (needs <= {CUP_REACH_M} m)"
        self.cup = cup
        return None

    def duration(self, world: "World") -> float:
        return 1.5

    def during(self, world: "World") -> Optional[str]:
        return None if self.cup.holder is None else f"cup {self.cup.id} was taken"

    def finish(self, world: "World") -> dict[str, Any]:
        self.cup.holder = f"robot:{self.robot.name}"
        self.robot.carrying = self.cup.id
        return {"cup": self.cup.id, "kind": self.cup.kind}


class HandOver(Timed):
    """Hand the carried cup to a user within 0.6 m (body gap); 1.5 s."""

    ARGS = (Arg("user", "string"),)

    def begin(self, world: "World") -> Optional[str]:
        if not self.robot.carrying:
            return "not carrying a cup"
        gap = user_gap(world, self.robot, self.args["user"])
        if gap is None:
            return f"no user named {self.args['user']!r}"
        if gap > HAND_REACH_M:
            return f"user {self.args['user']!r} is {gap:.2f} m away (needs <= {HAND_REACH_M} m)"
        return None

    def duration(self, world: "World") -> float:
        return 1.5

    def during(self, world: "World") -> Optional[str]:
        gap = user_gap(world, self.robot, self.args["user"])
        if gap is None or gap > HAND_REACH_M + 0.2:
            return f"user {self.args['user']!r} walked away"
        return None

    def finish(self, world: "World") -> dict[str, Any]:
        cup = world.cups[self.robot.carrying]
        cup.holder = f"user:{self.args['user']}"
        world.users[self.args["user"]].holding.append(cup.id)
        self.robot.carrying = None
        return {"cup": cup.id, "kind": cup.kind, "user": self.args["user"]}


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
                if not (k.isdigit() and 0 <= int(k) < N_LIGHTS):
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


class Drive(Timed):
    """Scout: run the wheels at left/right speeds (m/s) for duration_s; a bumper hit stops it."""

    ARGS = (
        Arg("left_mps", "number", lo=-0.6, hi=0.6),
        Arg("right_mps", "number", lo=-0.6, hi=0.6),
        Arg("duration_s", "number", lo=0.0, hi=600.0),
    )

    def duration(self, world: "World") -> float:
        return float(self.args["duration_s"])

    def control(self, world: "World", dt: float) -> None:
        self.robot.wheel_cmd = (float(self.args["left_mps"]), float(self.args["right_mps"]))

    def stop(self, world: "World") -> None:
        self.robot.wheel_cmd = None

    def finish(self, world: "World") -> dict[str, Any]:
        x, y = self.robot.pos
        return {"x": r(x, 3), "y": r(y, 3)}


class StandUp(Timed):
    """PINO gets up after a fall; 3 s (nothing to do when standing)."""

    ARGS = ()

    def duration(self, world: "World") -> float:
        return 3.0 if self.robot.fallen else 0.0

    def finish(self, world: "World") -> dict[str, Any]:
        self.robot.fallen = False
        return {"fallen": False}
