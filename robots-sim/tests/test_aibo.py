"""AIBO: posture transitions take time and end with the posture in the state; lights; walking."""

from __future__ import annotations

from conftest import Sim, only


def test_aibo_stand_sit_lie_down(sim: Sim) -> None:
    assert sim.state()["robots"]["aibo"]["posture"] == "stand"
    for aid, posture, secs in (("p1", "sit", 1.0), ("p2", "lie_down", 1.2), ("p3", "stand", 1.5)):
        start = only(sim.command("aibo", "set_posture", aid, posture=posture), "action_started")[0]
        mid = sim.state()["robots"]["aibo"]
        assert mid["posture_target"] == posture and mid["posture"] != posture
        end, _ = sim.run(aid)
        assert end["type"] == "action_ended" and end["result"]["posture"] == posture
        assert abs((end["t"] - start["t"]) - secs) <= 1 / 60 + 1e-6
        aibo = sim.state()["robots"]["aibo"]
        assert aibo["posture"] == posture and aibo["posture_target"] is None


def test_aibo_lie_down_action_and_no_walking_while_lying(sim: Sim) -> None:
    sim.command("aibo", "lie_down", "l1")
    end, _ = sim.run("l1")
    assert end["type"] == "action_ended" and sim.state()["robots"]["aibo"]["posture"] == "lie_down"
    evs = sim.command("aibo", "go_to", "w1", x=3.0, y=2.0)
    failed = only(evs, "action_failed", id="w1")
    assert failed and failed[0]["reason"].startswith("posture is lie_down")


def test_aibo_walks_to_user_and_lies_down_near_them(sim: Sim) -> None:
    sim.request("spawn_user", name="alice", x=4.0, y=1.2, heading_deg=90)
    sim.command("aibo", "approach_user", "a1", user="alice", distance_m=0.3)
    end, _ = sim.run("a1", max_s=30)
    assert end["type"] == "action_ended" and abs(end["result"]["gap_m"] - 0.3) <= 0.1
    assert end["t"] >= (1.7 - 0.7 - 0.1) / 0.3  # 1.7 m apart, stops 0.7 m centre to centre, at <= 0.3 m/s
    sim.command("aibo", "lie_down", "l1")
    assert sim.run("l1")[0]["type"] == "action_ended"


def test_aibo_lights(sim: Sim) -> None:
    sim.command("aibo", "set_lights", "x1", all="off", lights={"0": "red", "18": "#00ff00"})
    end, _ = sim.run("x1")
    lights = sim.state()["robots"]["aibo"]["lights"]
    assert len(lights) == 19 and lights[0] == "red" and lights[18] == "#00ff00" and lights[5] == "off"
    bad = sim.command("aibo", "set_lights", "x2", lights=["red"] * 18)
    assert bad[0]["type"] == "error" and bad[0]["field"] == "args.lights"


def test_a_light_index_that_is_a_digit_but_not_a_number_is_refused_as_an_index(sim: Sim) -> None:
    evs = sim.command("aibo", "set_lights", "l1", lights={"²": "red"})  # str.isdigit() is true for '²'
    assert [e["type"] for e in evs] == ["error"] and evs[0]["field"] == "args.lights.²", evs
    assert "internal error" not in evs[0]["message"]
