"""Scout: reaching goals, bumpers, sonar, carrying a cup from the counter to a user."""

from __future__ import annotations

import math

from conftest import Sim, only


def test_scout_reaches_goal_within_tolerance(sim: Sim) -> None:
    evs = sim.command("scout", "go_to", "g1", x=5.0, y=5.0)
    assert [e["type"] for e in evs] == ["ack", "action_started"]
    end, seen = sim.run("g1", max_s=30)
    assert end["type"] == "action_ended", end
    s = sim.state()["robots"]["scout"]
    assert math.hypot(s["x"] - 5.0, s["y"] - 5.0) <= 0.1
    assert only(seen, "sensor", robot="scout", sensor="arrival")
    assert 5.0 < end["t"] < 20.0  # ~4 m at 0.5 m/s plus turning: it took physical time
    assert s["actions"] == {}


def test_scout_go_to_with_final_heading(sim: Sim) -> None:
    sim.command("scout", "go_to", "g2", x=6.2, y=3.0, heading_deg=180)
    end, _ = sim.run("g2", max_s=20)
    assert end["type"] == "action_ended"
    assert abs(abs(end["result"]["heading_deg"]) - 180.0) <= 2.0


def test_scout_stops_on_bumper_hit_and_fails(sim: Sim) -> None:
    sim.request("add_obstacle", name="box", x=6.2, y=3.0, w=1.0, h=0.2)
    sim.command("scout", "go_to", "g3", x=6.2, y=4.0)
    end, seen = sim.run("g3", max_s=20)
    assert end["type"] == "action_failed"
    assert end["reason"] == "blocked: bumper 0"
    hits = only(seen, "sensor", robot="scout", sensor="bumper", pressed=True)
    assert hits and hits[0]["bumper"] == 0 and hits[0]["contact"] == "box"
    assert hits[0]["t"] == end["t"]  # stopped in the same step as the hit
    s = sim.state()["robots"]["scout"]
    assert s["v_mps"] == 0.0 and s["bumpers"][0] is True
    assert 2.6 <= s["y"] <= 2.72  # against the box's south face (y = 2.9) with its 0.2 m radius
    sim.step(1.0)
    assert sim.state()["robots"]["scout"]["y"] == s["y"]  # and stays put


def test_scout_stops_in_the_step_of_the_hit(sim: Sim) -> None:
    sim.request("add_obstacle", name="box", x=6.2, y=3.0, w=1.0, h=0.2)
    sim.request("stream", enabled=True, period_ms=1000 / 60)  # a state every step
    sim.command("scout", "go_to", "g3", x=6.2, y=4.0)
    end, seen = sim.run("g3", max_s=20)
    states = {e["t"]: e["robots"]["scout"] for e in only(seen, "state")}
    times = sorted(states)
    i = times.index(end["t"])
    before, at, after = states[times[i - 1]], states[times[i]], states[times[i + 1]]
    assert before["v_mps"] == 0.5 and at["v_mps"] == 0.0  # full speed, then stopped in the hit's step
    assert (after["x"], after["y"]) == (at["x"], at["y"])


def test_scout_rear_bumper_when_reversing(sim: Sim) -> None:
    sim.request("place_robot", robot="scout", x=6.2, y=0.6, heading_deg=90)
    sim.command("scout", "drive", "d1", left_mps=-0.3, right_mps=-0.3, duration_s=5)
    end, seen = sim.run("d1", max_s=10)
    assert end["type"] == "action_failed" and end["reason"] == "blocked: bumper 3"


def test_scout_sonar_sees_obstacle_and_wall(sim: Sim) -> None:
    sim.request("add_obstacle", name="box", x=6.2, y=3.0, w=1.0, h=0.2)
    sonar = sim.state()["robots"]["scout"]["sonar_m"]
    assert len(sonar) == 16
    assert abs(sonar[0] - 0.7) < 0.05  # ahead: box face at 2.9, sensor at 2.2
    assert abs(sonar[8] - 1.75) < 0.05  # behind: south wall surface at 0.05, sensor at 1.8
    assert all(0.0 <= v <= 5.0 for v in sonar)


def test_scout_carries_tea_from_counter_to_user(sim: Sim) -> None:
    far = sim.command("scout", "pick_up", "p0", cup="tea")
    assert only(far, "action_failed", id="p0")[0]["reason"].startswith("not near the counter")
    sim.command("scout", "go_to", "g", x=6.85, y=3.7)
    assert sim.run("g")[0]["type"] == "action_ended"
    sim.command("scout", "pick_up", "p1", cup="tea")
    end, _ = sim.run("p1")
    assert end["type"] == "action_ended" and end["result"]["kind"] == "tea"
    cup = end["result"]["cup"]
    sim.request("spawn_user", name="alice", x=5.0, y=2.0, heading_deg=0)
    sim.command("scout", "approach_user", "a1", user="alice")
    end, _ = sim.run("a1", max_s=30)
    assert end["type"] == "action_ended" and end["result"]["gap_m"] <= 0.6
    sim.command("scout", "hand_over", "h1", user="alice")
    end, _ = sim.run("h1")
    assert end["type"] == "action_ended" and end["result"] == {"cup": cup, "kind": "tea", "user": "alice", "duration_s": 1.5}
    st = sim.state()
    assert st["cups"][cup]["holder"] == "user:alice" and st["users"]["alice"]["holding"] == [cup]
    assert st["robots"]["scout"]["carrying"] is None


def test_scout_puts_the_carried_cup_down_on_the_counter(sim: Sim) -> None:
    sim.command("scout", "go_to", "g", x=6.85, y=3.7)
    assert sim.run("g")[0]["type"] == "action_ended"
    sim.command("scout", "pick_up", "p1", cup="tea")
    cup = sim.run("p1")[0]["result"]["cup"]
    sim.command("scout", "go_to", "g2", x=5.0, y=3.0)
    assert sim.run("g2", max_s=20)[0]["type"] == "action_ended"
    far = sim.command("scout", "put_down", "b0")
    assert only(far, "action_failed", id="b0")[0]["reason"].startswith("not near the counter")
    assert sim.state()["robots"]["scout"]["carrying"] == cup
    sim.command("scout", "go_to", "g3", x=6.85, y=4.6)
    assert sim.run("g3", max_s=20)[0]["type"] == "action_ended"
    sim.command("scout", "put_down", "b1")
    end, _ = sim.run("b1")
    assert end["type"] == "action_ended" and end["result"]["cup"] == cup and end["result"]["kind"] == "tea"
    st = sim.state()
    assert st["robots"]["scout"]["carrying"] is None
    assert st["cups"][cup]["holder"] is None
    assert st["cups"][cup]["x"] == 7.3 and abs(st["cups"][cup]["y"] - 4.6) < 0.1
    sim.command("scout", "pick_up", "p2", cup="coffee")
    end, _ = sim.run("p2")
    assert end["type"] == "action_ended" and end["result"]["kind"] == "coffee"


def test_scout_put_down_with_empty_gripper_ends_at_once(sim: Sim) -> None:
    sim.command("scout", "put_down", "b2")
    end, _ = sim.run("b2")
    assert end["type"] == "action_ended" and end["result"] == {"cup": None, "kind": None, "duration_s": 0.0}


def test_a_drive_longer_than_the_default_timeout_runs_its_whole_duration(sim: Sim) -> None:
    sim.command("scout", "drive", "d1", left_mps=0.0, right_mps=0.0, duration_s=150.0)  # no timeout_s given
    end, _ = sim.run("d1", max_s=160)
    assert end["type"] == "action_ended" and abs(end["t"] - 150.0) < 0.05, end
    sim.command("scout", "drive", "d2", timeout_s=5.0, left_mps=0.0, right_mps=0.0, duration_s=150.0)
    end, _ = sim.run("d2", max_s=10)
    assert end["type"] == "action_failed" and end["reason"] == "timeout after 5 s", end  # an explicit timeout holds


def test_scout_that_bumped_into_a_wall_can_turn_away_and_leave(sim: Sim) -> None:
    sim.request("place_robot", robot="scout", x=6.2, y=5.5, heading_deg=90)
    sim.command("scout", "drive", "d", left_mps=0.3, right_mps=0.3, duration_s=3)
    end, _ = sim.run("d")
    assert end["reason"] == "blocked: bumper 0"  # against the north wall
    sim.command("scout", "go_to", "g", x=6.2, y=3.0)  # turning about sweeps the wall's contact past bumpers 1 and 2
    end, seen = sim.run("g", max_s=20)
    assert end["type"] == "action_ended", (end, only(seen, "sensor", sensor="bumper"))
    sim.request("add_obstacle", name="box", x=6.2, y=2.0, w=1.0, h=0.2)
    sim.command("scout", "go_to", "g2", x=6.2, y=1.0)  # a new contact still stops it
    assert sim.run("g2", max_s=20)[0]["reason"] == "blocked: bumper 0"
