"""Test harness: a manual-mode simulator driven through the real protocol dispatcher.

Requests go in as JSON text lines exactly as on stdin, and the events that come out are the
encoded JSON lines, parsed back; nothing of the world is mocked.
"""

from __future__ import annotations

import json
import math
from typing import Any, Optional

import pytest

from kicnp_sim.protocol import Dispatcher, encode
from kicnp_sim.world import World


class Sim:
    """A world in manual mode plus the full log of event lines it produced."""

    def __init__(self, seed: int = 42):
        self.world = World(seed=seed)
        self.disp = Dispatcher(self.world, manual=True, time_scale=1.0)
        self.lines: list[str] = []
        self.n = 0
        self.disp.hello()
        self._drain()

    def _drain(self) -> list[dict[str, Any]]:
        lines = [encode(e) for e in self.world.drain()]
        self.lines += lines
        return [json.loads(s) for s in lines]

    def send(self, req: dict[str, Any] | str) -> list[dict[str, Any]]:
        self.disp.handle_line(req if isinstance(req, str) else json.dumps(req))
        return self._drain()

    def request(self, type_: str, **fields: Any) -> list[dict[str, Any]]:
        self.n += 1
        return self.send({"id": fields.pop("id", f"r{self.n}"), "type": type_, **fields})

    def command(self, robot: str, action: str, id: str, timeout_s: Optional[float] = None, **args: Any) -> list[dict[str, Any]]:
        req: dict[str, Any] = {"id": id, "type": "command", "robot": robot, "action": action, "args": args}
        if timeout_s is not None:
            req["timeout_s"] = timeout_s
        return self.send(req)

    def step(self, seconds: float, until_idle: bool = False) -> list[dict[str, Any]]:
        return self.request("step", seconds=seconds, until_idle=until_idle)

    def run(self, action_id: str, max_s: float = 60.0) -> tuple[dict[str, Any], list[dict[str, Any]]]:
        """Step until the action ends or fails; returns (that event, all events on the way)."""
        seen: list[dict[str, Any]] = []
        t = 0.0
        while t < max_s:
            seen += self.step(0.5)
            done = [e for e in seen if e["type"] in ("action_ended", "action_failed") and e.get("id") == action_id]
            if done:
                return done[0], seen
            t += 0.5
        raise AssertionError(f"action {action_id} still running after {max_s} s")

    def state(self) -> dict[str, Any]:
        evs = self.request("query")
        return next(e for e in evs if e["type"] == "state")


def only(events: list[dict[str, Any]], type_: str, **match: Any) -> list[dict[str, Any]]:
    """The events of a type whose fields equal the given values."""
    return [e for e in events if e["type"] == type_ and all(e.get(k) == v for k, v in match.items())]


def cosine(a: list[float], b: list[float]) -> float:
    dot = sum(x * y for x, y in zip(a, b))
    return dot / (math.sqrt(sum(x * x for x in a)) * math.sqrt(sum(y * y for y in b)))


@pytest.fixture
def sim() -> Sim:
    return Sim()
