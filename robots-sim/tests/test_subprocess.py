"""The real program: `python -m kicnp_sim` as a subprocess speaking JSON lines on stdin/stdout."""

from __future__ import annotations

import json
import queue
import subprocess
import sys
import threading
import time
from typing import Any

import pytest


class Proc:
    """A running simulator with a reader thread, so reads can time out instead of hanging."""

    def __init__(self, *args: str):
        self.p = subprocess.Popen([sys.executable, "-m", "kicnp_sim", *args], stdin=subprocess.PIPE,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, bufsize=1)
        self.q: "queue.Queue[str | None]" = queue.Queue()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        assert self.p.stdout is not None
        for line in self.p.stdout:
            self.q.put(line)
        self.q.put(None)

    def send(self, obj: dict[str, Any] | str) -> None:
        assert self.p.stdin is not None
        self.p.stdin.write((obj if isinstance(obj, str) else json.dumps(obj)) + "\n")
        self.p.stdin.flush()

    def next(self, timeout: float = 10.0) -> dict[str, Any]:
        line = self.q.get(timeout=timeout)
        assert line is not None, "stdout closed"
        return json.loads(line)  # every stdout line must be protocol JSON

    def until(self, pred: Any, timeout: float = 10.0) -> list[dict[str, Any]]:
        """Events up to and including the first one that matches pred."""
        out: list[dict[str, Any]] = []
        end = time.monotonic() + timeout
        while True:
            out.append(self.next(max(0.01, end - time.monotonic())))
            if pred(out[-1]):
                return out

    def close_and_wait(self, timeout: float = 10.0) -> int:
        assert self.p.stdin is not None
        self.p.stdin.close()
        return self.p.wait(timeout=timeout)


@pytest.fixture
def procs() -> Any:
    started: list[Proc] = []

    def start(*args: str) -> Proc:
        started.append(Proc(*args))
        return started[-1]

    yield start
    for pr in started:
        if pr.p.poll() is None:
            pr.p.kill()
            pr.p.wait()


def test_manual_mode_over_pipes(procs: Any) -> None:
    pr = procs("--manual", "--seed", "42")
    hello = pr.next()
    assert hello["type"] == "hello" and hello["mode"] == "manual" and hello["seed"] == 42
    pr.send("this is not json")
    err = pr.next()
    assert err["type"] == "error" and err["id"] is None and "malformed JSON" in err["message"]
    assert pr.p.poll() is None  # still alive
    assert pr.p.stdin is not None
    pr.p.stdin.buffer.write(b"\xff\xfe{not utf-8}\n")
    pr.p.stdin.flush()
    assert pr.next()["type"] == "error"
    assert pr.p.poll() is None
    pr.send({"id": "q1", "type": "query"})
    assert pr.next()["type"] == "ack"
    st = pr.next()
    assert st["type"] == "state" and st["id"] == "q1" and st["t"] == 0.0
    pr.send({"id": "c1", "type": "command", "robot": "robovie", "action": "say", "args": {"text": "Hello there"}})
    evs = pr.until(lambda e: e["type"] == "utterance")
    assert [e["type"] for e in evs] == ["ack", "action_started", "utterance"]
    pr.send({"id": "s1", "type": "step", "seconds": 1.0})
    evs = pr.until(lambda e: e.get("id") == "s1")
    assert [e["type"] for e in evs] == ["action_ended", "ack"] and evs[-1]["t"] == 1.0
    assert pr.close_and_wait() == 0  # EOF: clean exit


def test_realtime_mode_runs_faster_than_real_time_and_shuts_down(procs: Any) -> None:
    pr = procs("--time-scale", "20", "--seed", "1")
    assert pr.next()["mode"] == "realtime"
    t0 = time.monotonic()
    pr.send({"id": "g", "type": "command", "robot": "scout", "action": "go_to", "args": {"x": 6.2, "y": 4.0}})
    evs = pr.until(lambda e: e.get("id") == "g" and e["type"] in ("action_ended", "action_failed"), timeout=15)
    wall = time.monotonic() - t0
    assert evs[-1]["type"] == "action_ended" and evs[-1]["t"] >= 3.5  # ~1.9 m at 0.5 m/s of sim time...
    assert wall < evs[-1]["t"] / 2  # ...in much less wall time (20x nominal; slack for a loaded machine)
    pr.send({"id": "x", "type": "step", "seconds": 1})
    assert pr.next()["field"] == "type"  # step needs --manual
    pr.send({"id": "bye", "type": "shutdown"})
    assert pr.until(lambda e: e.get("id") == "bye")[-1]["type"] == "ack"
    assert pr.p.wait(timeout=10) == 0


def test_as_fast_as_possible_and_eof(procs: Any) -> None:
    pr = procs("--time-scale", "0")
    pr.next()
    pr.send({"id": "q", "type": "query"})
    st = pr.until(lambda e: e["type"] == "state")[-1]
    assert st["id"] == "q"
    assert pr.close_and_wait() == 0


def test_non_finite_or_extreme_face_numbers_are_refused_and_the_simulator_keeps_going(procs: Any) -> None:
    pr = procs("--manual")
    pr.next()
    zeros = ",0" * 14
    for rid, first in (("n", "NaN"), ("i", "Infinity"), ("m", "-Infinity")):
        pr.send('{"id":"%s","type":"spawn_user","name":"u%s","face":[%s,1%s]}' % (rid, rid, first, zeros))
        err = pr.next()
        assert err["type"] == "error" and err["id"] == rid and err["field"] == "face", err
    assert pr.p.poll() is None  # still alive
    for rid, first in (("big", "1e308,1e308"), ("tiny", "1e-320,0")):  # scaled, not overflowed or flushed to zero
        pr.send('{"id":"%s","type":"spawn_user","name":"u%s","face":[%s%s]}' % (rid, rid, first, zeros))
        ack = pr.next()
        assert ack["type"] == "ack" and ack["id"] == rid, ack
        assert abs(sum(v * v for v in ack["result"]["face"]) - 1.0) < 1e-5, ack
    pr.send({"id": "q", "type": "query"})
    assert pr.until(lambda e: e["type"] == "state")[-1]["id"] == "q"
    assert pr.close_and_wait() == 0


@pytest.mark.parametrize("args, says", [
    (["--time-scale", "nan"], "--time-scale must be within [0, 1000]"),
    (["--log-level", "verbose"], "--log-level"),
])
def test_bad_command_line_options_are_usage_errors_not_tracebacks(args: list[str], says: str) -> None:
    p = subprocess.run([sys.executable, "-m", "kicnp_sim", *args], stdin=subprocess.DEVNULL, capture_output=True,
                       text=True, timeout=20)
    assert p.returncode == 2 and says in p.stderr and "Traceback" not in p.stderr, (p.returncode, p.stderr)
    assert p.stdout == ""  # no hello for a simulator that will not run


def test_a_stray_print_in_simulator_code_goes_to_stderr_not_into_the_protocol_stream() -> None:
    # A robot's author debugging with print() (here without a newline, which would glue it to the next event).
    code = ("import sys, kicnp_sim.skills as sk, kicnp_sim.__main__ as m\n"
            "orig = sk.Say.start\n"
            "def start(self, world):\n"
            "    print('debug: saying', self.args['text'], end='')\n"
            "    return orig(self, world)\n"
            "sk.Say.start = start\n"
            "sys.exit(m.main(['--manual']))\n")
    lines = "\n".join(json.dumps(r) for r in (
        {"id": "c1", "type": "command", "robot": "robovie", "action": "say", "args": {"text": "Hello"}},
        {"id": "s1", "type": "step", "seconds": 1.0})) + "\n"
    p = subprocess.run([sys.executable, "-c", code], input=lines, capture_output=True, text=True, timeout=20)
    assert p.returncode == 0, p.stderr
    events = [json.loads(line) for line in p.stdout.splitlines()]  # every line is protocol JSON
    assert [e["type"] for e in events if e.get("id") in ("c1", "s1")] == [
        "ack", "action_started", "utterance", "action_ended", "ack"]
    assert "debug: saying Hello" in p.stderr


def _peak_rss_kib(pid: int) -> int:
    """The most resident memory the process has had (VmHWM), in KiB."""
    with open(f"/proc/{pid}/status") as status:
        return next(int(line.split()[1]) for line in status if line.startswith("VmHWM:"))


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads the peak memory from /proc")
@pytest.mark.parametrize("args", [["--manual"], ["--time-scale", "0"]], ids=["manual", "realtime"])
def test_a_line_far_over_the_limit_is_refused_before_it_ends_and_skipped_without_being_kept(procs: Any,
                                                                                           args: list[str]) -> None:
    pr = procs(*args)
    pr.next()  # hello
    before = _peak_rss_kib(pr.p.pid)
    assert pr.p.stdin is not None
    chunk = "x" * 1_000_000  # the test's own memory stays at one chunk
    pr.p.stdin.write('{"id":"big","type":"query","pad":"')
    for _ in range(30):
        pr.p.stdin.write(chunk)
    pr.p.stdin.flush()
    # 30 million characters and no newline yet: the error comes now, not when (or if) the line ends.
    err = pr.next(timeout=20)
    assert err == {"type": "error", "t": err["t"], "id": None, "field": None, "message": (
        "request: a line longer than the protocol's limit of 10000000 characters was skipped up to its newline and "
        "not handled; its id cannot be known, as the line was not kept")}, err
    for _ in range(30):
        pr.p.stdin.write(chunk)
    pr.send('"}')  # the line ends, 60 million characters long
    pr.send({"id": "q", "type": "query"})
    evs = pr.until(lambda e: e["type"] == "state", timeout=20)
    assert [(e["type"], e["id"]) for e in evs if e["type"] in ("ack", "error", "state")] == [("ack", "q"), ("state", "q")]
    # Kept whole, the line alone would be 60 MB (the unbounded readline() took over 200 MB). Read with the limit, at
    # most a line of the limit is held: about 20 MB at the peak, inside readline.
    grew = _peak_rss_kib(pr.p.pid) - before
    assert grew < 40_000, f"the simulator's peak memory grew by {grew} KiB reading one over-long line"
    assert pr.close_and_wait() == 0
