"""A time scale the machine cannot reach is said once on stderr, not left for the user to discover."""

from __future__ import annotations

import io
import subprocess
import sys
import time

from kicnp_sim.server import ScaleWatch


def test_watch_warns_once_when_the_achieved_scale_falls_well_short() -> None:
    err = io.StringIO()
    watch = ScaleWatch(err, window=2.0)
    dt = 1.0 / 60
    watch.reset(now=0.0, steps=0)
    watch.observe(scale=1000.0, now=1.0, steps=36_000, dt=dt)  # within the first window: too early to judge
    assert err.getvalue() == ""
    watch.observe(scale=1000.0, now=2.0, steps=72_000, dt=dt)  # 1200 simulated seconds in 2 s: 600x
    text = err.getvalue()
    assert text.count("\n") == 1, text
    assert "time scale 1000" in text and "about 600x" in text, text
    watch.observe(scale=1000.0, now=4.0, steps=108_000, dt=dt)  # still short: not said again
    assert err.getvalue() == text


def test_watch_is_silent_when_the_scale_is_reached_or_as_fast_as_possible() -> None:
    err = io.StringIO()
    watch = ScaleWatch(err, window=2.0)
    dt = 1.0 / 60
    watch.reset(now=0.0, steps=0)
    watch.observe(scale=20.0, now=2.0, steps=2_300, dt=dt)  # 38.3 s in 2 s: ~19x, close enough
    watch.observe(scale=0.0, now=4.0, steps=2_400, dt=dt)  # 0 = as fast as possible: nothing to fall short of
    assert err.getvalue() == ""


def test_simulator_asked_for_more_than_it_can_reach_says_so_once_on_stderr() -> None:
    p = subprocess.Popen([sys.executable, "-m", "kicnp_sim", "--time-scale", "1000", "--hz", "1000"],
                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        time.sleep(3.5)  # a million steps per wall second: no machine keeps up
    finally:
        out, err = p.communicate(input="", timeout=20)  # EOF: clean exit
    assert p.returncode == 0, err
    assert err.count("time scale 1000") == 1, err
    assert "reaches only about" in err, err
    assert all(line.startswith("{") for line in out.splitlines())  # stdout stays protocol JSON
