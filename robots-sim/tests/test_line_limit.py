"""A request line longer than the protocol's limit, in process, through the run loops: the read itself is bounded, the
line is skipped with an ``error`` that has no id, and the next line is handled, in manual and real-time mode alike.

The limit is lowered through the loops' ``max_line`` so that no test holds megabytes; test_subprocess.py has the real
program at the real limit.
"""

from __future__ import annotations

import io
import json
import time
from typing import Any, Union

import pytest

from kicnp_sim.protocol import Dispatcher
from kicnp_sim.server import INPUT_QUEUE_LINES, run_manual, run_realtime
from kicnp_sim.world import World

LIMIT = 200
MODES = ["manual", "realtime"]


def skipped(limit: int) -> str:
    return (f"request: a line longer than the protocol's limit of {limit} characters was skipped up to its newline "
            "and not handled; its id cannot be known, as the line was not kept")


def run(mode: str, inp: Any, limit: int = LIMIT) -> list[tuple[str, Any]]:
    """Runs the loop of ``mode`` over ``inp`` to its end: the (type, id) of each ack, state and error, with an error's
    message in place of its id's absence."""
    world = World(seed=42)
    disp = Dispatcher(world, manual=mode == "manual", time_scale=0.0)  # real time as fast as possible
    disp.hello()
    out = io.StringIO()
    if mode == "manual":
        assert run_manual(disp, inp, out, max_line=limit) == 0
    else:
        assert run_realtime(disp, inp, out, err=io.StringIO(), max_line=limit) == 0
    events = [json.loads(line) for line in out.getvalue().splitlines()]
    return [(e["type"], e["id"] if e["id"] is not None else e.get("message")) for e in events
            if e["type"] in ("ack", "state", "error")]


def query(rid: str, length: int = 0) -> str:
    """A query line (without its newline), padded with blanks inside the object to ``length`` characters."""
    line = json.dumps({"id": rid, "type": "query"})
    return line[:-1] + " " * max(0, length - len(line)) + "}"


class LazyStream:
    """A text stream whose lines are made only as they are read; it notes the most characters one read returned.

    Each part is text, or a number n standing for n characters 'x' (no newline) made piece by piece. ``readline()``
    without a size, as a reader without a bound does it, makes the whole rest of the line at once."""

    def __init__(self, *parts: Union[str, int]):
        self.parts = list(parts)
        self.longest = 0

    def readline(self, size: int = -1) -> str:
        pieces: list[str] = []
        n = 0
        while self.parts and (size < 0 or n < size):
            part, room = self.parts[0], (size - n if size >= 0 else None)
            if isinstance(part, int):
                take = part if room is None else min(part, room)
                pieces.append("x" * take)
                rest: Union[str, int] = part - take
            else:
                end = part.find("\n") + 1 or len(part)
                take = end if room is None else min(end, room)
                pieces.append(part[:take])
                rest = part[take:]
            n += take
            if rest:
                self.parts[0] = rest
            else:
                self.parts.pop(0)
            if pieces[-1].endswith("\n"):
                break
        line = "".join(pieces)
        self.longest = max(self.longest, len(line))
        return line


@pytest.mark.parametrize("mode", MODES)
def test_a_line_over_the_limit_gets_an_error_without_id_and_the_next_line_is_handled(mode: str) -> None:
    big = json.dumps({"id": "big", "type": "spawn_user", "name": "x" * (3 * LIMIT)})
    text = "\n".join([query("q1"), big, query("q2")]) + "\n"
    assert run(mode, io.StringIO(text)) == [("ack", "q1"), ("state", "q1"), ("error", skipped(LIMIT)),
                                            ("ack", "q2"), ("state", "q2")]


@pytest.mark.parametrize("mode", MODES)
def test_a_line_of_exactly_the_limit_is_handled_and_one_character_more_is_not(mode: str) -> None:
    lines = [query("at", LIMIT), query("over", LIMIT + 1), query("after"), query("over-at-eof", LIMIT + 1)]
    assert [len(line) for line in lines[:2]] == [LIMIT, LIMIT + 1]
    assert run(mode, io.StringIO("\n".join(lines))) == [  # the last line ends at EOF, with no newline
        ("ack", "at"), ("state", "at"), ("error", skipped(LIMIT)), ("ack", "after"), ("state", "after"),
        ("error", skipped(LIMIT))]
    assert run(mode, io.StringIO(query("at-eof", LIMIT))) == [("ack", "at-eof"), ("state", "at-eof")]


@pytest.mark.parametrize("mode", MODES)
def test_no_read_returns_more_than_the_limit_plus_one_characters_of_a_long_line(mode: str) -> None:
    stream = LazyStream(query("q1") + "\n", '{"id":"big","type":"query","pad":"', 1_000_000, '"}\n',
                        query("q2") + "\n")
    assert run(mode, stream) == [("ack", "q1"), ("state", "q1"), ("error", skipped(LIMIT)), ("ack", "q2"),
                                 ("state", "q2")]
    assert stream.longest == LIMIT + 1  # a reader without a bound would have made the million characters at once


def test_realtime_mode_reads_at_most_a_bounded_number_of_lines_ahead_of_the_ones_it_has_handled() -> None:
    """A writer faster than the loop (here: a stream that is always ready, and a slow handler) is held back by the
    bounded queue between the reader thread and the loop, instead of the queue growing with everything written."""
    lines = 300
    handled = 0
    ahead = 0

    class Counting(io.StringIO):
        def readline(self, size: int = -1) -> str:  # type: ignore[override]
            nonlocal ahead
            line = super().readline(size)
            if line:
                ahead = max(ahead, self.read_so_far - handled)
                self.read_so_far += 1
            return line

    stream = Counting("".join(query(f"q{i}") + "\n" for i in range(lines)))
    stream.read_so_far = 0  # type: ignore[attr-defined]
    world = World(seed=42)
    disp = Dispatcher(world, manual=False, time_scale=0.0)
    disp.hello()
    handle = disp.handle_line

    def slow(line: str) -> None:
        nonlocal handled
        time.sleep(0.001)
        handle(line)
        handled += 1

    disp.handle_line = slow  # type: ignore[method-assign]
    assert run_realtime(disp, stream, io.StringIO(), err=io.StringIO()) == 0
    assert handled == lines
    assert ahead <= INPUT_QUEUE_LINES + 2  # the queue, the line the loop holds, the line the reader holds
