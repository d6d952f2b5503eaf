"""The JSON-lines protocol: parse and validate requests, apply them to the world, encode events.

Every request gets exactly one ``ack`` or ``error`` carrying its id (a ``step``'s ack comes
after the events the step produced). Errors name the request id and the offending field.
See PROTOCOL.md for every message type.
"""

from __future__ import annotations

import json
import logging
import math
from typing import Any, Callable, Optional

from . import PROTOCOL_VERSION, __version__, room
from .specs import Arg
from .geometry import from_deg
from .users import FACE_DIM, USER_RADIUS
from .world import BusyError, World

log = logging.getLogger("kicnp_sim.protocol")
MAX_STEP_S = 3600.0
# Characters (code points) of one line, either way. The platform's JSON reader (Jackson) refuses a string longer than
# 20,000,000 UTF-16 units and would drop the whole event, leaving the request it answers waiting for its timeout; half
# that, in code points, can never reach it, even when every character needs two units.
MAX_LINE = 10_000_000
SELF_ACK = ("command", "query", "step")  # handlers that send their own ack at the right moment
MARGIN = 0.1  # positions must be at least this far inside the walls


class ProtocolError(Exception):
    """A request that cannot be carried out: which request, which field, and why."""

    def __init__(self, req_id: Any, field: Optional[str], message: str):
        where = f"request {req_id!r}" if req_id is not None else "request"
        super().__init__(f"{where}: field {field!r} {message}" if field else f"{where}: {message}")
        self.req_id = req_id
        self.field = field


def encode(event: dict[str, Any]) -> str:
    """One event as one compact JSON line (no newline).

    An event whose line would be longer than MAX_LINE is not sent: an ``error`` event with its id (if it has one) says
    so instead, so that a request waiting for it fails at once, with the reason, rather than at its timeout."""
    line = json.dumps(event, separators=(",", ":"), ensure_ascii=False, allow_nan=False)
    if len(line) <= MAX_LINE:
        return line
    req_id = event.get("id")
    what = f"request {req_id!r}: its {event['type']} event" if req_id is not None else f"a {event['type']} event"
    message = (f"{what} would be a line of {len(line)} characters, longer than the protocol's limit of {MAX_LINE} "
               "characters; it was not sent")
    log.error("%s", message)
    return json.dumps({"type": "error", "t": event["t"], "id": req_id, "field": None, "message": message},
                      separators=(",", ":"), ensure_ascii=False, allow_nan=False)


def _finite(value: Any) -> bool:
    """A JSON number that is finite as a float (JSON also parses NaN, Infinity and integers too big for a float)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return False
    try:
        return math.isfinite(value)
    except OverflowError:
        return False


def check_value(req_id: Any, field: str, value: Any, arg: Arg) -> Any:
    """Validate one value against an Arg spec; returns it (numbers as float)."""
    kind = arg.kind
    if kind == "number":
        if not _finite(value):
            raise ProtocolError(req_id, field, "must be a finite number")
        value = float(value)
        if arg.lo is not None and value < arg.lo or arg.hi is not None and value > arg.hi:
            raise ProtocolError(req_id, field, f"must be within [{arg.lo:g}, {arg.hi:g}], got {value:g}")
    elif kind == "string":
        if not isinstance(value, str) or not value:
            raise ProtocolError(req_id, field, "must be a non-empty string")
        if arg.choices and value not in arg.choices:
            raise ProtocolError(req_id, field, f"must be one of {', '.join(arg.choices)}; got {value!r}")
    elif kind == "bool" and not isinstance(value, bool):
        raise ProtocolError(req_id, field, "must be true or false")
    elif kind == "object" and not isinstance(value, dict):
        raise ProtocolError(req_id, field, "must be a JSON object")
    elif kind == "array" and not isinstance(value, list):
        raise ProtocolError(req_id, field, "must be a JSON array")
    return value


def check_fields(req_id: Any, obj: dict[str, Any], specs: tuple[Arg, ...], prefix: str = "") -> dict[str, Any]:
    """Validate an object against Arg specs: no unknown fields, required present, defaults."""
    known = {a.name for a in specs}
    for key in obj:
        if key not in known:
            raise ProtocolError(req_id, prefix + key, f"is not known (expected: {', '.join(sorted(known)) or 'none'})")
    out: dict[str, Any] = {}
    for a in specs:
        if obj.get(a.name) is None:
            if a.required:
                raise ProtocolError(req_id, prefix + a.name, "is required")
            out[a.name] = a.default
        else:
            out[a.name] = check_value(req_id, prefix + a.name, obj[a.name], a)
    return out


def num(name: str, required: bool = True, lo: Optional[float] = None, hi: Optional[float] = None, default: Any = None) -> Arg:
    return Arg(name, "number", required, default, lo=lo, hi=hi)


def text(name: str, required: bool = True) -> Arg:
    return Arg(name, "string", required)


X = num("x", lo=MARGIN, hi=room.ROOM_W - MARGIN)
Y = num("y", lo=MARGIN, hi=room.ROOM_H - MARGIN)
HEADING = num("heading_deg", False, -360.0, 360.0)
COMMON = (text("id"), text("type"))
REQUESTS: dict[str, tuple[Arg, ...]] = {
    "command": (text("robot"), text("action"), Arg("args", "object", False), num("timeout_s", False, 0.001, 86400.0),
                num("progress_s", False, 0.01, 3600.0)),
    "spawn_user": (text("name"), num("x", False, X.lo, X.hi), num("y", False, Y.lo, Y.hi), HEADING,
                   Arg("face", "array", False)),
    "move_user": (text("name"), X, Y, HEADING, num("speed", False, 0.01, 3.0)),
    "remove_user": (text("name"),),
    "place_robot": (text("robot"), X, Y, HEADING),
    "add_obstacle": (text("name", False), X, Y, num("w", lo=0.02, hi=room.ROOM_W), num("h", lo=0.02, hi=room.ROOM_H)),
    "cancel": (text("robot"), text("action_id")),
    "query": (),
    "stream": (Arg("enabled", "bool"), num("period_ms", False, 1.0, 3_600_000.0, 500.0)),
    "step": (num("seconds", lo=0.0, hi=MAX_STEP_S), Arg("until_idle", "bool", False, False)),
    "set_time_scale": (num("time_scale", lo=0.0, hi=1000.0),),
    "shutdown": (),
}


class Dispatcher:
    """Applies protocol requests to a world; events accumulate in ``world.events``."""

    def __init__(self, world: World, manual: bool, time_scale: float):
        self.world = world
        self.manual = manual
        self.time_scale = time_scale
        self.shutdown = False
        self.handlers: dict[str, Callable[[Any, dict[str, Any]], Optional[dict[str, Any]]]] = {
            name: getattr(self, "_" + name) for name in REQUESTS
        }

    def hello(self) -> None:
        from .robots import ROBOT_CLASSES

        self.world.emit(
            "hello", protocol=PROTOCOL_VERSION, version=__version__, seed=self.world.seed, dt=self.world.dt,
            mode="manual" if self.manual else "realtime", time_scale=self.time_scale, room=room.describe(),
            face_dim=FACE_DIM, requests=sorted(REQUESTS),
            robots={n: c.capabilities() for n, c in ROBOT_CLASSES.items()},
        )

    def handle_line(self, line: str) -> None:
        """Handle one input line; never raises for bad input (it becomes an error event)."""
        line = line.strip()
        if not line:
            return
        req_id = None
        try:
            try:
                req = json.loads(line)
            except json.JSONDecodeError as exc:
                raise ProtocolError(None, None, f"malformed JSON: {exc.msg} at column {exc.colno}") from None
            if not isinstance(req, dict):
                raise ProtocolError(None, None, "must be a JSON object")
            req_id = req.get("id")
            if not isinstance(req_id, str) or not req_id:
                req_id = None if not isinstance(req_id, (str, int)) else req_id
                raise ProtocolError(req_id, "id", "is required and must be a non-empty string")
            # What it says would come back too long for the platform to read. A line from stdin never gets here that
            # long (the server's read_lines skips it, unkept, and calls line_too_long instead); this is for a caller
            # that hands a line in directly.
            if len(line) > MAX_LINE:
                raise ProtocolError(req_id, None, f"is a line of {len(line)} characters, longer than the protocol's "
                                                  f"limit of {MAX_LINE} characters; it was not handled")
            rtype = req.get("type")
            if rtype not in REQUESTS:
                raise ProtocolError(req_id, "type", f"must be one of {', '.join(sorted(REQUESTS))}; got {rtype!r}")
            fields = check_fields(req_id, req, COMMON + REQUESTS[rtype])
            result = self.handlers[rtype](req_id, fields)
            if rtype not in SELF_ACK:
                self.ack(req_id, result)
        except ProtocolError as exc:
            self.world.emit("error", id=exc.req_id, field=exc.field, message=str(exc))
        except Exception as exc:  # a bug: report it, log it, keep serving
            log.exception("internal error handling %r", line[:200])
            self.world.emit("error", id=req_id, field=None, message=f"request {req_id!r}: internal error: {exc!r}")

    def line_too_long(self, limit: int) -> None:
        """Reports a request line longer than ``limit`` characters, which the reader skipped without keeping it.

        Nothing of the line is kept (keeping it is what a line with no end would make unbounded), so its id cannot be
        known: the error has none, and says so, so that the sender can tell why no request of its own was answered."""
        message = str(ProtocolError(None, None, f"a line longer than the protocol's limit of {limit} characters was "
                                                "skipped up to its newline and not handled; its id cannot be known, "
                                                "as the line was not kept"))
        self.world.emit("error", id=None, field=None, message=message)

    def ack(self, req_id: Any, result: Optional[dict[str, Any]] = None) -> None:
        if result is None:
            self.world.emit("ack", id=req_id)
        else:
            self.world.emit("ack", id=req_id, result=result)

    # ---- handlers (return the ack result, or None) --------------------------------------
    def _robot(self, req_id: Any, name: str) -> Any:
        if name not in self.world.robots:
            raise ProtocolError(req_id, "robot", f"must be one of {', '.join(self.world.robots)}; got {name!r}")
        return self.world.robots[name]

    def _user(self, req_id: Any, name: str) -> Any:
        if name not in self.world.users:
            raise ProtocolError(req_id, "name", f"names no user in the room: {name!r}")
        return self.world.users[name]

    def _command(self, req_id: Any, f: dict[str, Any]) -> None:
        robot = self._robot(req_id, f["robot"])
        spec = robot.ACTIONS.get(f["action"])
        if spec is None:
            raise ProtocolError(req_id, "action", f"{robot.name} cannot {f['action']!r}; it can: {', '.join(robot.ACTIONS)}")
        args = check_fields(req_id, f["args"] or {}, spec.args, "args.")
        validate = getattr(spec.factory, "validate", None)
        problem = validate(args) if validate else None
        if problem:
            raise ProtocolError(req_id, problem[0], problem[1])
        args = {k: v for k, v in args.items() if v is not None}
        if any(a.id == req_id for rb in self.world.robots.values() for a in rb.actions.values()):
            raise ProtocolError(req_id, "id", "is the id of an action still running")
        try:
            self.world.check_free(robot, spec.parts)
        except BusyError as exc:
            raise ProtocolError(req_id, "action", f"refused: {exc}") from None
        action = spec.factory(robot, args)
        action.id, action.name, action.parts = req_id, spec.name, spec.parts
        action.timeout_s = f["timeout_s"]  # None: the action's default, known once it has started
        action.progress_s = f["progress_s"]
        self.ack(req_id)
        self.world.start(robot, action)

    def _clear(self, req_id: Any, x: float, y: float, radius: float, me: Any = None, users: bool = False) -> None:
        """Refuse a position where a body of this radius would overlap a wall, the counter or an obstacle; with ``me``
        (the body being put there, or True for a new user) also a robot, and with ``users`` also a user: the physics
        would shove it out of the way, through a wall if need be."""
        hit = self.world.static_overlap(x, y, radius)
        if hit is None and me is not None:
            hit = self.world.body_overlap(x, y, radius, me, users)
        if hit:
            raise ProtocolError(req_id, "x", f"({x:g}, {y:g}) overlaps {hit}")

    def _spawn_user(self, req_id: Any, f: dict[str, Any]) -> dict[str, Any]:
        if f["name"] in self.world.users:
            raise ProtocolError(req_id, "name", f"is already taken by a user in the room: {f['name']!r}")
        if (f["x"] is None) != (f["y"] is None):
            raise ProtocolError(req_id, "x" if f["x"] is None else "y", "must be given together with the other coordinate")
        face = f["face"]
        if face is not None:
            if len(face) != FACE_DIM or any(not _finite(v) for v in face):
                raise ProtocolError(req_id, "face", f"must be an array of {FACE_DIM} finite numbers")
            if not any(face):
                raise ProtocolError(req_id, "face", "must not be all zeros")
        x, y = (f["x"], f["y"]) if f["x"] is not None else room.DOOR_ENTRY
        self._clear(req_id, x, y, USER_RADIUS, me=True)
        heading = from_deg(90.0 if f["heading_deg"] is None else f["heading_deg"])
        user = self.world.spawn_user(f["name"], x, y, heading, face)
        return {"name": user.name, **user.state(), "face": [round(v, 6) for v in user.face]}

    def _move_user(self, req_id: Any, f: dict[str, Any]) -> None:
        user = self._user(req_id, f["name"])
        self._clear(req_id, f["x"], f["y"], USER_RADIUS, me=user.body if f["speed"] is None else None)
        if f["heading_deg"] is not None:
            user.body.angle = from_deg(f["heading_deg"])
        if f["speed"] is None:
            user.target = None
            user.body.position = (f["x"], f["y"])
            self.world.space.reindex_shapes_for_body(user.body)
        else:
            user.walk_to(f["x"], f["y"], f["speed"])

    def _remove_user(self, req_id: Any, f: dict[str, Any]) -> None:
        self._user(req_id, f["name"])
        self.world.remove_user(f["name"])

    def _place_robot(self, req_id: Any, f: dict[str, Any]) -> None:
        robot = self._robot(req_id, f["robot"])
        if "base" in robot.actions:
            raise ProtocolError(req_id, "robot", f"{robot.name} is moving ({robot.actions['base'].id!r}); cancel it first")
        self._clear(req_id, f["x"], f["y"], robot.radius, me=robot.body, users=True)
        heading = robot.heading if f["heading_deg"] is None else from_deg(f["heading_deg"])
        self.world.place_robot(robot, f["x"], f["y"], heading)

    def _add_obstacle(self, req_id: Any, f: dict[str, Any]) -> dict[str, Any]:
        name = f["name"] or f"obstacle-{len(self.world.obstacles) + 1}"
        if name in self.world.obstacles:
            raise ProtocolError(req_id, "name", f"is already taken by an obstacle: {name!r}")
        hit = self.world.box_overlap(f["x"], f["y"], f["w"], f["h"])
        if hit:  # a robot inside a static box could never get out
            raise ProtocolError(req_id, "x", f"a {f['w']:g} x {f['h']:g} box at ({f['x']:g}, {f['y']:g}) overlaps {hit}")
        self.world.add_obstacle(name, f["x"], f["y"], f["w"], f["h"])
        return {"name": name}

    def _cancel(self, req_id: Any, f: dict[str, Any]) -> None:
        robot = self._robot(req_id, f["robot"])
        action = next((a for a in robot.running() if a.id == f["action_id"]), None)
        if action is None:
            raise ProtocolError(req_id, "action_id", f"names no running action of {robot.name}: {f['action_id']!r}")
        robot.halt()
        self.world.finish(action, ("failed", f"cancelled by {req_id}"))

    def _query(self, req_id: Any, f: dict[str, Any]) -> None:
        self.ack(req_id)
        self.world.emit("state", id=req_id, **self.world.state())

    def _stream(self, req_id: Any, f: dict[str, Any]) -> dict[str, Any]:
        self.world.set_stream(f["period_ms"] / 1000.0 if f["enabled"] else None)
        return {"enabled": f["enabled"], "period_ms": f["period_ms"]}

    def _step(self, req_id: Any, f: dict[str, Any]) -> None:
        if not self.manual:
            raise ProtocolError(req_id, "type", "'step' needs manual mode (start with --manual)")
        n = round(f["seconds"] / self.world.dt)
        done = 0
        while done < n and not (f["until_idle"] and not self.world.busy()):
            self.world.step()
            done += 1
        self.ack(req_id, {"steps": done, "idle": not self.world.busy()})

    def _set_time_scale(self, req_id: Any, f: dict[str, Any]) -> dict[str, Any]:
        self.time_scale = f["time_scale"]
        return {"time_scale": self.time_scale}

    def _shutdown(self, req_id: Any, f: dict[str, Any]) -> None:
        self.shutdown = True
