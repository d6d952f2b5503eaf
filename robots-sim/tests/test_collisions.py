"""Robots that meet: a robot standing still is braked and holds its place; the one driving into it is stopped."""

from __future__ import annotations

import pytest

from conftest import Sim, only


@pytest.mark.parametrize(
    ("driver", "standing", "reason"),
    [
        ("robovie", "scout", "blocked: no progress for 3 s"),  # 40 kg into 25 kg: shoved it 2.4 m before brakes
        ("robovie", "aibo", "blocked: no progress for 3 s"),  # the heaviest into the lightest (1.6 kg)
        ("scout", "robovie", "blocked: bumper 0"),
        ("pino", "aibo", "stumbled"),
    ],
)
def test_a_robot_driving_into_a_standing_one_is_stopped_and_does_not_move_it(
    sim: Sim, driver: str, standing: str, reason: str
) -> None:
    sim.request("place_robot", robot=standing, x=5.0, y=3.0, heading_deg=0)
    sim.request("place_robot", robot=driver, x=3.0, y=3.0, heading_deg=0)
    before = sim.state()["robots"][standing]
    sim.command(driver, "go_to", "g", x=7.0, y=3.0)
    end, _ = sim.run("g", max_s=30)
    after = sim.state()["robots"]
    assert end["type"] == "action_failed" and end["reason"] == reason, end
    assert abs(after[standing]["x"] - before["x"]) <= 0.005 and abs(after[standing]["y"] - before["y"]) <= 0.005
    assert after[driver]["x"] < 5.0  # stopped short of it, not through it


def test_a_braked_robot_drives_off_when_commanded(sim: Sim) -> None:
    sim.request("place_robot", robot="scout", x=5.0, y=3.0, heading_deg=0)
    sim.request("place_robot", robot="robovie", x=3.0, y=3.0, heading_deg=0)
    sim.command("robovie", "go_to", "g", x=7.0, y=3.0)
    end, _ = sim.run("g", max_s=30)
    assert end["type"] == "action_failed"
    sim.command("scout", "go_to", "away", x=6.5, y=3.0)  # the standing robot drives off: its brakes come off
    end, seen = sim.run("away", max_s=30)
    assert end["type"] == "action_ended", end
    assert only(seen, "sensor", robot="scout", sensor="arrival")
    assert abs(sim.state()["robots"]["scout"]["x"] - 6.5) <= 0.1


@pytest.mark.parametrize(("first", "second"), [("robovie", "aibo"), ("robovie", "scout"), ("pino", "aibo")])
def test_two_robots_driving_at_each_other_both_hold_and_neither_shoves_the_other(
    sim: Sim, first: str, second: str
) -> None:
    sim.request("place_robot", robot=first, x=2.0, y=5.0, heading_deg=0)  # a clear lane along the north wall
    sim.request("place_robot", robot=second, x=4.0, y=5.0, heading_deg=180)
    sim.command(first, "go_to", "a", x=6.5, y=5.0)
    sim.command(second, "go_to", "b", x=1.0, y=5.0)
    end_a, seen = sim.run("a", max_s=30)
    end_b = only(seen, "action_failed", id="b") or only(seen, "action_ended", id="b")
    if not end_b:
        end_b = [sim.run("b", max_s=30)[0]]
    robots = sim.state()["robots"]
    # both fail where they met: neither reached its goal through the other, neither was pushed back
    assert end_a["type"] == "action_failed" and end_a["reason"].startswith("blocked"), end_a
    assert end_b[0]["type"] == "action_failed" and end_b[0]["reason"].startswith("blocked"), end_b
    gap = robots[second]["x"] - robots[first]["x"]
    assert 2.0 < robots[first]["x"] and robots[second]["x"] < 4.0
    radii = {name: sim.world.robots[name].radius for name in (first, second)}
    assert radii[first] + radii[second] - 0.005 <= gap <= radii[first] + radii[second] + 0.1, gap


def test_a_robot_held_by_another_drives_on_once_the_other_has_gone(sim: Sim) -> None:
    sim.request("place_robot", robot="robovie", x=3.0, y=3.0, heading_deg=0)
    sim.request("place_robot", robot="aibo", x=4.5, y=3.0, heading_deg=180)
    sim.command("robovie", "go_to", "a", x=6.0, y=3.0, stall_s=30)
    sim.command("aibo", "go_to", "b", x=1.0, y=3.0, stall_s=2)
    end_b, _ = sim.run("b", max_s=30)
    assert end_b["type"] == "action_failed", end_b
    sim.command("aibo", "go_to", "away", x=3.9, y=5.0)  # it steps aside, and robovie is free to go on
    end_a, _ = sim.run("a", max_s=60)
    assert end_a["type"] == "action_ended", end_a
    assert abs(sim.state()["robots"]["robovie"]["x"] - 6.0) <= 0.1
