"""Argument and action specs: what each action accepts, used to validate commands and to
describe each robot's capabilities in the hello event."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable


@dataclass(frozen=True)
class Arg:
    """One argument of an action: its JSON kind, whether it is required, its limits."""

    name: str
    kind: str  # "number" | "string" | "bool" | "object" | "array" | "any"
    required: bool = True
    default: Any = None
    choices: tuple[str, ...] | None = None
    lo: float | None = None
    hi: float | None = None
    doc: str = ""

    def describe(self) -> dict[str, Any]:
        d: dict[str, Any] = {"type": self.kind, "required": self.required}
        if self.default is not None:
            d["default"] = self.default
        if self.choices:
            d["choices"] = list(self.choices)
        if self.lo is not None:
            d["min"] = self.lo
        if self.hi is not None:
            d["max"] = self.hi
        if self.doc:
            d["doc"] = self.doc
        return d


@dataclass(frozen=True)
class ActionSpec:
    """What a robot can be commanded: name, parts it claims, args, and the class to build."""

    name: str
    parts: tuple[str, ...]
    factory: Callable[..., Any]  # the Action class to build
    args: tuple[Arg, ...] = field(default_factory=tuple)
    doc: str = ""

    def describe(self) -> dict[str, Any]:
        return {"parts": list(self.parts), "args": {a.name: a.describe() for a in self.args}, "doc": self.doc}
