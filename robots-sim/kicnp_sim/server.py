"""Run loops: manual stepping (deterministic; the world moves only on 'step') and real time.

In real time a reader thread feeds stdin lines into a queue, and the main loop steps the world
so that simulated time follows wall time times the time scale (0 = as fast as possible). Only
this module reads the wall clock; the world never does. Only protocol JSON goes to stdout.
Both loops read stdin through ``read_lines``, which never holds more of one line than the
protocol's limit allows, so a line with no end cannot make the simulator's memory grow.
"""

from __future__ import annotations

import queue
import sys
import threading
import time
from typing import IO, Iterator, Optional, Union

from .protocol import MAX_LINE, Dispatcher, encode

MAX_CATCH_UP_STEPS = 600  # per loop turn; beyond this the clock is re-anchored (we fell behind)
FAST_BATCH_STEPS = 20  # steps between input checks when running as fast as possible
WATCH_WINDOW = 2.0  # wall seconds over which the achieved time scale is measured
SHORT_FRACTION = 0.8  # below this share of the requested scale, the machine is not keeping up
INPUT_QUEUE_LINES = 32  # lines read ahead in real-time mode; when full, the reader waits (and so does the writer)
SKIP_CHUNK = 65_536  # characters read (and dropped) at a time while skipping the rest of an over-long line


class ScaleWatch:
    """Measures the time scale the run loop achieves and says once, on stderr, when it falls well short.

    A scale the machine cannot reach (each physics step costs more than the wall time the scale allows)
    would otherwise just run slower than asked, silently: ``--time-scale 1000`` giving about 600x.
    """

    def __init__(self, err: IO[str], window: float = WATCH_WINDOW):
        self.err = err
        self.window = window
        self.warned = False
        self.since_wall = 0.0
        self.since_steps = 0

    def reset(self, now: float, steps: int) -> None:
        """Starts a new measurement, e.g. after the scale changed."""
        self.since_wall, self.since_steps = now, steps

    def observe(self, scale: float, now: float, steps: int, dt: float) -> None:
        """Checks the scale reached since the last window closed, once a window of wall time has passed."""
        elapsed = now - self.since_wall
        if elapsed < self.window:
            return
        achieved = (steps - self.since_steps) * dt / elapsed
        self.reset(now, steps)
        if self.warned or scale <= 0 or achieved >= SHORT_FRACTION * scale:
            return
        self.warned = True
        self.err.write(f"kicnp_sim: warning: time scale {scale:g} was asked for, but this machine reaches only about "
                       f"{achieved:.0f}x (a physics step takes longer than the {dt / scale * 1e3:.3g} ms of wall time "
                       f"that scale allows); simulated time runs slower than asked.\n")
        self.err.flush()


def flush(disp: Dispatcher, out: IO[str]) -> None:
    """Write the pending events, one JSON object per line."""
    events = disp.world.drain()
    if events:
        out.write("".join(encode(e) + "\n" for e in events))
        out.flush()


class LineTooLong:
    """Stands, among the lines ``read_lines`` yields, for a line longer than its limit, of which nothing is kept."""

    def __init__(self, limit: int):
        self.limit = limit


Line = Union[str, LineTooLong]


def read_lines(inp: IO[str], max_line: int = MAX_LINE) -> Iterator[Line]:
    """The lines of ``inp`` (each with its newline, the last one perhaps without), read so that no more than
    ``max_line + 1`` characters of one line are ever held.

    ``readline()`` alone would hold a whole line before anything could check its length, and a line that never ends
    (a peer that writes no newline) would grow without bound. So each line is read with a limit: a line longer than
    ``max_line`` characters (before its newline) is yielded as a :class:`LineTooLong` as soon as ``max_line + 1`` of
    its characters have come, those are dropped, and the rest of it, up to its newline, is read ``SKIP_CHUNK``
    characters at a time (at most ``max_line + 1``) and dropped too, when the next line is asked for; the line after
    it is read as usual.
    """
    skip = min(SKIP_CHUNK, max_line + 1)
    while True:
        line = inp.readline(max_line + 1)
        if not line:
            return
        if len(line) <= max_line or line.endswith("\n"):
            yield line
            continue
        del line  # not kept while the caller reports it, nor while the rest is skipped
        yield LineTooLong(max_line)
        while True:
            rest = inp.readline(skip)
            if not rest or rest.endswith("\n"):
                break


def _handle(disp: Dispatcher, line: Line) -> None:
    """One line from ``read_lines``, as both loops handle it."""
    if isinstance(line, LineTooLong):
        disp.line_too_long(line.limit)
    else:
        disp.handle_line(line)


def run_manual(disp: Dispatcher, inp: IO[str], out: IO[str], max_line: int = MAX_LINE) -> int:
    """Handle lines until EOF or shutdown; the world advances only on 'step' requests.

    A line longer than ``max_line`` characters gets an ``error`` and is skipped (see ``read_lines``)."""
    flush(disp, out)
    lines = read_lines(inp, max_line)
    while not disp.shutdown:
        line = next(lines, None)
        if line is None:
            break
        _handle(disp, line)
        flush(disp, out)
    return 0


def _reader(inp: IO[str], q: "queue.Queue[Optional[Line]]", max_line: int) -> None:
    for line in read_lines(inp, max_line):
        q.put(line)
    q.put(None)


def run_realtime(disp: Dispatcher, inp: IO[str], out: IO[str], err: Optional[IO[str]] = None,
                 max_line: int = MAX_LINE) -> int:
    """Step the world against the wall clock scaled by the time scale, handling input as it comes.

    When the machine cannot keep up with the scale, a warning goes once to ``err`` (default stderr). A line longer
    than ``max_line`` characters gets an ``error`` and is skipped, as in ``run_manual`` (see ``read_lines``)."""
    # Bounded, so that a writer faster than the loop makes the pipe (and then the writer) wait instead of this
    # process's memory grow: at most INPUT_QUEUE_LINES lines of at most max_line characters wait here.
    q: "queue.Queue[Optional[Line]]" = queue.Queue(maxsize=INPUT_QUEUE_LINES)
    threading.Thread(target=_reader, args=(inp, q, max_line), daemon=True, name="stdin-reader").start()
    world = disp.world
    flush(disp, out)
    scale = disp.time_scale
    anchor_wall, anchor_sim = time.monotonic(), world.steps
    watch = ScaleWatch(err if err is not None else sys.stderr)
    watch.reset(anchor_wall, anchor_sim)
    while True:
        if disp.time_scale != scale:  # re-anchor on a time-scale change
            scale, anchor_wall, anchor_sim = disp.time_scale, time.monotonic(), world.steps
            watch.reset(anchor_wall, anchor_sim)
        watch.observe(scale, time.monotonic(), world.steps, world.dt)
        if scale == 0:
            wait: Optional[float] = 0.0
            for _ in range(FAST_BATCH_STEPS):
                world.step()
        else:
            due = anchor_sim + int((time.monotonic() - anchor_wall) * scale / world.dt)
            n = 0
            while world.steps < due and n < MAX_CATCH_UP_STEPS:
                world.step()
                n += 1
            if n == MAX_CATCH_UP_STEPS:
                anchor_wall, anchor_sim = time.monotonic(), world.steps
            next_due = anchor_wall + (world.steps + 1 - anchor_sim) * world.dt / scale
            wait = max(0.0, next_due - time.monotonic())
        flush(disp, out)
        try:
            line = q.get(timeout=wait) if wait else q.get_nowait()
        except queue.Empty:
            continue
        while True:
            if line is None:
                return 0
            _handle(disp, line)
            flush(disp, out)
            if disp.shutdown:
                return 0
            try:
                line = q.get_nowait()
            except queue.Empty:
                break
