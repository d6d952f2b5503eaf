"""Timed skills: actions that take a known time once their preconditions hold.

This module has the Timed base and the humanoid skills: speaking, arm and head motion, shaking
hands, PINO standing up (Scout's are in skills_scout.py, AIBO's in skills_aibo.py). Each one checks its
preconditions against the world when it starts (failing with a reason when they do not hold),
may fail while running (the user walked away), and applies its effect when its time is up.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

from .actions import Action, Outcome
from .specs import Arg
from .geometry import dist, r

if TYPE_CHECKING:
    from .world import World

HAND_REACH_M = 0.6  # gap between bodies for shaking hands and handing over a cup
CUP_REACH_M = 0.4  # gap between the robot's body and a cup on the counter
SAY_S_PER_CHAR = 0.06
SAY_MIN_S = 0.5
ARM_POSES = ("down", "up", "wave", "shake")


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

    def default_timeout(self) -> float:
        """Its known duration never times out by default (a long drive or speech)."""
        return max(super().default_timeout(), self.dur + 1.0)

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
        if gap is None:
            return f"user {self.args['user']!r} left"
        if gap > HAND_REACH_M + 0.2:
            return f"user {self.args['user']!r} walked away"
        return None

    def stop(self, world: "World") -> None:
        if hasattr(self, "before"):
            self.robot.arms.update(self.before)

    def finish(self, world: "World") -> dict[str, Any]:
        return {"user": self.args["user"]}


class StandUp(Timed):
    """PINO gets up after a fall; 3 s (nothing to do when standing)."""

    ARGS = ()

    def duration(self, world: "World") -> float:
        return 3.0 if self.robot.fallen else 0.0

    def finish(self, world: "World") -> dict[str, Any]:
        self.robot.fallen = False
        return {"fallen": False}
