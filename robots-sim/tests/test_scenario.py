"""The scenario of the paper's Table 5, played through the protocol from start to end."""

from __future__ import annotations

import json

from conftest import Sim, only


def ok(sim: Sim, robot: str, action: str, id: str, max_s: float = 60.0, **args: object) -> dict:
    sim.command(robot, action, id, **args)
    end, _ = sim.run(id, max_s)
    assert end["type"] == "action_ended", end
    return end


def test_table5_scenario(sim: Sim) -> None:
    sim.request("spawn_user", name="userA")  # comes in at the door
    sim.request("move_user", name="userA", x=4.0, y=2.0, speed=0.8)
    seen = only(sim.step(2.0), "sensor", robot="robovie", sensor="face_seen")
    assert seen and seen[0]["truth_user"] == "userA" and len(seen[0]["face"]) == 16
    ok(sim, "robovie", "say", "r1", text="How are you! I have never seen you before. What is your name?")
    ok(sim, "robovie", "say", "r2", text="Hi, XXX. Nice to meet you. Welcome you to visit my room.")
    ok(sim, "robovie", "approach_user", "r3", user="userA", distance_m=0.3)
    ok(sim, "robovie", "shake_hands", "r4", user="userA")
    ok(sim, "robovie", "say", "r5", text="This is my friend, PINO.")
    ok(sim, "pino", "approach_user", "p1", user="userA", distance_m=0.4)
    ok(sim, "pino", "shake_hands", "p2", user="userA")
    ok(sim, "robovie", "say", "r6", text="What do you want to drink?")
    ok(sim, "scout", "go_to", "s1", x=6.85, y=3.7)
    ok(sim, "scout", "pick_up", "s2", cup="tea")
    ok(sim, "scout", "approach_user", "s3", user="userA", distance_m=0.3)
    ok(sim, "scout", "hand_over", "s4", user="userA")
    ok(sim, "robovie", "say", "r7", text="This is a robot dog AIBO. Please enjoy yourself with it.")
    ok(sim, "aibo", "approach_user", "a1", user="userA", distance_m=0.3)
    ok(sim, "aibo", "lie_down", "a2")
    st = sim.state()
    assert st["users"]["userA"]["holding"] == ["tea-1"]
    assert st["robots"]["aibo"]["posture"] == "lie_down"
    assert st["robots"]["pino"]["fallen"] is False
    assert len(only([json.loads(x) for x in sim.lines], "utterance")) == 5
