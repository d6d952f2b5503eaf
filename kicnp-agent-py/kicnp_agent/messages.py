"""The messages an agent's program sees, as immutable values, and the slot values the protocol carries.

They mirror the records of org.kicnp.protocol.Message that an agent receives; the wire's camelCase members become
snake_case attributes, and ``from`` (a Python keyword) becomes ``sender``.
"""
import math
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

STAGES = ("started", "progress", "ended", "failed")
CHANGES = ("added", "replaced", "removed")


@dataclass(frozen=True)
class Ref:
    """A slot value that names a frame (``{"ref": "userA"}`` on the wire: TYPE_INSTANCE or TYPE_FRAME)."""
    name: str


def value_to_json(value, where):
    """A Python slot value as the protocol writes it; ``where`` names the value in the error's sentence.

    JSON has no NaN or infinity, and the server would read a bare string "NaN" as text: such a value is refused here
    rather than sent as something else.
    """
    if isinstance(value, bool) or isinstance(value, str) or isinstance(value, int):
        return value
    if isinstance(value, float):
        if math.isnan(value) or math.isinf(value):
            raise ValueError("%s is %r, which JSON cannot carry; send a finite number." % (where, value))
        return value
    if isinstance(value, Ref):
        return {"ref": value.name}
    if isinstance(value, (list, tuple)):
        return [value_to_json(item, "%s[%d]" % (where, i)) for i, item in enumerate(value)]
    raise TypeError("%s is a %s; a slot value is a str, int, float, bool, Ref or a list of them."
                    % (where, type(value).__name__))


_NON_FINITE = {"NaN": math.nan, "Infinity": math.inf, "-Infinity": -math.inf}


def value_from_json(value):
    """A slot value as received: ``{"ref": name}`` becomes a :class:`Ref`, ``{"float": "NaN"}`` (or ``"Infinity"``,
    ``"-Infinity"``: a float JSON has no number for) a float, arrays become lists."""
    if isinstance(value, dict):
        if "float" in value:
            return _NON_FINITE[value["float"]]
        return Ref(value["ref"])
    if isinstance(value, list):
        return [value_from_json(item) for item in value]
    return value


@dataclass(frozen=True)
class Command:
    """A command for a robot: ``action`` with its ``args`` (text to text)."""
    id: str
    robot: str
    action: str
    args: Dict[str, str] = field(default_factory=dict)


@dataclass(frozen=True)
class Feedback:
    """A robot's report on a command: ``stage`` is one of started, progress, ended, failed."""
    id: str
    robot: str
    stage: str
    detail: str
    progress: Optional[float] = None

    @property
    def terminal(self):
        """Whether this report ends the command (ended or failed)."""
        return self.stage in ("ended", "failed")


@dataclass(frozen=True)
class Relay:
    """A message relayed from another agent; ``sender`` is the wire's ``from``, stamped by the server."""
    id: str
    sender: str
    subject: str
    body: str
    to_agent: Optional[str] = None
    to_kind: Optional[str] = None


@dataclass(frozen=True)
class Changed:
    """A change to a frame of a subscribed class: ``change`` is added, replaced or removed.

    ``frame`` is the frame's XML after the change (None when removed); ``values`` are a sensor signal's values,
    typed as the sensor message carried them (None for other frames).
    """
    of_class: str
    change: str
    name: str
    frame: Optional[str] = None
    values: Optional[List[object]] = None


@dataclass(frozen=True)
class Snapshot:
    """What :meth:`Agent.snapshot` answers: the frames, and ``server_time``, the server's clock (epoch milliseconds)
    when it read them — the clock of the times they hold, such as a sensor signal's ``expires`` — or None from a
    server that does not say."""
    frames: List[object]
    server_time: Optional[int] = None


@dataclass(frozen=True)
class Reason:
    """Why an instance exists (the answer to ``why``), back to the stimuli through ``supports``."""
    instance: str
    of_class: str
    derived: bool
    binding: Dict[str, str]
    conditions: Tuple[str, ...]
    supports: Tuple["Reason", ...]

    @staticmethod
    def from_json(m):
        return Reason(m["instance"], m["ofClass"], m["derived"], dict(m["binding"]), tuple(m["conditions"]),
                      tuple(Reason.from_json(s) for s in m["supports"]))


@dataclass(frozen=True)
class ProofNode:
    """One answer of ``prove``: an instance of ``of_class`` that exists (``instance``) or could be derived (None)."""
    of_class: str
    instance: Optional[str]
    slots: Dict[str, "ProofNode"]
    assumptions: Tuple[str, ...]

    @staticmethod
    def from_json(m):
        return ProofNode(m["ofClass"], m.get("instance"),
                         {slot: ProofNode.from_json(node) for slot, node in m["slots"].items()},
                         tuple(m["assumptions"]))


@dataclass(frozen=True)
class SlotCandidates:
    """For ``why_not``: the instances a required slot could hold, and those its condition turned away."""
    slot: str
    argument: str
    condition: str
    candidates: Tuple[str, ...]
    rejected: Tuple[str, ...]
    candidate_count: int
    rejected_count: int


@dataclass(frozen=True)
class BindingOutcome:
    """For ``why_not``: one binding of the required slots and what stops it (``outcome``, ``reason``)."""
    binding: Dict[str, str]
    outcome: str
    reason: str


@dataclass(frozen=True)
class NotFired:
    """Why a behavior frame has not fired: a one-sentence ``summary``, then the slots' candidates and the bindings."""
    frame: str
    summary: str
    slots: Tuple[SlotCandidates, ...]
    bindings: Tuple[BindingOutcome, ...]
    truncated: bool

    @staticmethod
    def from_json(m):
        slots = tuple(SlotCandidates(s["slot"], s["argument"], s["condition"], tuple(s["candidates"]),
                                     tuple(s["rejected"]), s["candidateCount"], s["rejectedCount"])
                      for s in m["slots"])
        bindings = tuple(BindingOutcome(dict(b["binding"]), b["outcome"], b["reason"]) for b in m["bindings"])
        return NotFired(m["frame"], m["summary"], slots, bindings, m["truncated"])
