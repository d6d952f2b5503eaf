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
