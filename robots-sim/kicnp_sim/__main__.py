"""Command line: ``python -m kicnp_sim [--seed N] [--time-scale X] [--manual] [--audio-dir DIR]``.

Prints a hello event, then speaks the JSON-lines protocol on stdin/stdout (see PROTOCOL.md).
Logs go to stderr. Exits 0 on EOF or a shutdown request.
"""

from __future__ import annotations

import argparse
import logging
import sys
from typing import Optional

from .audio import Speaker
from .protocol import Dispatcher
from .server import run_manual, run_realtime
from .world import World


LOG_LEVELS = ("DEBUG", "INFO", "WARNING", "ERROR", "CRITICAL")


def parse_args(argv: Optional[list[str]]) -> argparse.Namespace:
    p = argparse.ArgumentParser(prog="python -m kicnp_sim", description="K-ICNP robot simulator (JSON lines on stdin/stdout)")
    p.add_argument("--seed", type=int, default=0, help="seed for faces and sensor noise (default 0)")
    p.add_argument("--time-scale", type=float, default=1.0,
                   help="simulated seconds per wall second; 0 = as fast as possible (default 1)")
    p.add_argument("--manual", action="store_true", help="advance only on 'step' requests (deterministic)")
    p.add_argument("--hz", type=float, default=60.0, help="physics steps per simulated second (default 60)")
    p.add_argument("--audio-dir", help="write a WAV per utterance here when espeak-ng is installed")
    p.add_argument("--log-level", default="WARNING", type=str.upper, choices=LOG_LEVELS,
                   help="stderr log level (default WARNING)")
    a = p.parse_args(argv)
    if not 0.0 <= a.time_scale <= 1000.0:  # also NaN
        p.error("--time-scale must be within [0, 1000]")
    if not 10.0 <= a.hz <= 1000.0:
        p.error("--hz must be within [10, 1000]")
    return a


def main(argv: Optional[list[str]] = None) -> int:
    a = parse_args(argv)
    sys.stdin.reconfigure(encoding="utf-8", errors="replace")  # bad bytes become a JSON error, not a crash
    sys.stdout.reconfigure(encoding="utf-8")
    protocol_out = sys.stdout
    sys.stdout = sys.stderr  # a stray print() in simulator code goes to the log, never into the protocol stream
    logging.basicConfig(stream=sys.stderr, level=a.log_level, format="%(levelname)s %(name)s: %(message)s")
    speaker = Speaker(a.audio_dir) if a.audio_dir else None
    world = World(seed=a.seed, dt=1.0 / a.hz, audio=speaker)
    disp = Dispatcher(world, manual=a.manual, time_scale=a.time_scale)
    disp.hello()
    try:
        run = run_manual if a.manual else run_realtime
        return run(disp, sys.stdin, protocol_out)
    except KeyboardInterrupt:
        return 0
    except BrokenPipeError:
        return 0
    finally:
        sys.stdout = protocol_out
        if speaker:
            speaker.close()


if __name__ == "__main__":
    sys.exit(main())
