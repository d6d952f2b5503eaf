"""Run loops: manual stepping (deterministic; the world moves only on 'step') and real time.

In real time a reader thread feeds stdin lines into a queue, and the main loop steps the world
so that simulated time follows wall time times the time scale (0 = as fast as possible). Only
this module reads the wall clock; the world never does. Only protocol JSON goes to stdout.
"""

from __future__ import annotations

import queue
import threading
import time
from typing import IO, Optional

from .protocol import Dispatcher, encode

MAX_CATCH_UP_STEPS = 600  # per loop turn; beyond this the clock is re-anchored (we fell behind)
FAST_BATCH_STEPS = 20  # steps between input checks when running as fast as possible


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


def run_realtime(disp: Dispatcher, inp: IO[str], out: IO[str]) -> int:
    """Step the world against the wall clock scaled by the time scale, handling input as it comes."""
    q: "queue.Queue[Optional[str]]" = queue.Queue()
    threading.Thread(target=_reader, args=(inp, q), daemon=True, name="stdin-reader").start()
    world = disp.world
    flush(disp, out)
    scale = disp.time_scale
    anchor_wall, anchor_sim = time.monotonic(), world.steps
    while True:
        if disp.time_scale != scale:  # re-anchor on a time-scale change
            scale, anchor_wall, anchor_sim = disp.time_scale, time.monotonic(), world.steps
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
