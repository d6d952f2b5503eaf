"""Run loops: manual stepping (deterministic; the world moves only on 'step') and real time.

In real time a reader thread feeds stdin lines into a queue, and the main loop steps the world
so that simulated time follows wall time times the time scale (0 = as fast as possible). Only
this module reads the wall clock; the world never does. Only protocol JSON goes to stdout.
"""

from __future__ import annotations

import queue
import sys
import threading
import time
from typing import IO, Optional

from .protocol import Dispatcher, encode

MAX_CATCH_UP_STEPS = 600  # per loop turn; beyond this the clock is re-anchored (we fell behind)
FAST_BATCH_STEPS = 20  # steps between input checks when running as fast as possible
WATCH_WINDOW = 2.0  # wall seconds over which the achieved time scale is measured
SHORT_FRACTION = 0.8  # below this share of the requested scale, the machine is not keeping up


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


def run_manual(disp: Dispatcher, inp: IO[str], out: IO[str]) -> int:
    """Handle lines until EOF or shutdown; the world advances only on 'step' requests."""
    flush(disp, out)
    while not disp.shutdown:
        line = inp.readline()
        if not line:
            break
        disp.handle_line(line)
        flush(disp, out)
    return 0


def _reader(inp: IO[str], q: "queue.Queue[Optional[str]]") -> None:
    for line in iter(inp.readline, ""):
        q.put(line)
    q.put(None)


def run_realtime(disp: Dispatcher, inp: IO[str], out: IO[str], err: Optional[IO[str]] = None) -> int:
    """Step the world against the wall clock scaled by the time scale, handling input as it comes.

    When the machine cannot keep up with the scale, a warning goes once to ``err`` (default stderr)."""
    q: "queue.Queue[Optional[str]]" = queue.Queue()
    threading.Thread(target=_reader, args=(inp, q), daemon=True, name="stdin-reader").start()
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
            disp.handle_line(line)
            flush(disp, out)
            if disp.shutdown:
                return 0
            try:
                line = q.get_nowait()
            except queue.Empty:
                break
