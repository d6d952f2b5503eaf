"""Protocol errors and bookkeeping, in process: every request gets one ack or one error."""

from __future__ import annotations

import json
import math
import re

from conftest import Sim, only


def test_hello_lists_robots_and_capabilities() -> None:
    sim = Sim(seed=5)
    hello = json.loads(sim.lines[0])
    assert hello["type"] == "hello" and hello["seed"] == 5 and hello["t"] == 0.0
    assert set(hello["robots"]) == {"robovie", "pino", "scout", "aibo"}
    assert "say" in hello["robots"]["robovie"]["actions"]
    assert hello["robots"]["scout"]["actions"]["go_to"]["args"]["x"]["required"] is True


def test_malformed_and_invalid_requests_give_errors_naming_id_and_field(sim: Sim) -> None:
    cases = [
        ("{not json", None, None),
        ('["a list"]', None, None),
        ('{"type":"query"}', None, "id"),
        ('{"id":"a","type":"fly"}', "a", "type"),
        ('{"id":"b","type":"command","robot":"r2d2","action":"go_to"}', "b", "robot"),
        ('{"id":"c","type":"command","robot":"scout","action":"say","args":{"text":"x"}}', "c", "action"),
        ('{"id":"d","type":"command","robot":"scout","action":"go_to","args":{"x":"far","y":1}}', "d", "args.x"),
        ('{"id":"e","type":"command","robot":"scout","action":"go_to","args":{"x":1}}', "e", "args.y"),
        ('{"id":"f","type":"command","robot":"scout","action":"go_to","args":{"x":1,"y":1,"speed":3}}', "f", "args.speed"),
        ('{"id":"g","type":"spawn_user","name":"z","face":[1,2,3]}', "g", "face"),
        ('{"id":"h","type":"spawn_user","name":"z","x":50,"y":1}', "h", "x"),
        ('{"id":"i","type":"move_user","name":"nobody","x":1,"y":1}', "i", "name"),
        ('{"id":"j","type":"command","robot":"aibo","action":"set_posture","args":{"posture":"fly"}}', "j", "args.posture"),
        ('{"id":"k","type":"query","extra":1}', "k", "extra"),
    ]
    for line, rid, field in cases:
        evs = sim.send(line)
        assert [e["type"] for e in evs] == ["error"], line
        assert evs[0]["id"] == rid and evs[0]["field"] == field, (line, evs[0])
        if rid is not None:
            assert repr(rid) in evs[0]["message"]
        if field is not None:
            assert repr(field) in evs[0]["message"]
    assert sim.step(0.5)[-1]["type"] == "ack"  # still working


def test_step_refused_in_realtime_mode() -> None:
    sim = Sim()
    sim.disp.manual = False
    evs = sim.request("step", id="s", seconds=1.0)
    assert evs[0]["type"] == "error" and evs[0]["field"] == "type"


def test_timeout_and_cancel(sim: Sim) -> None:
    sim.command("scout", "go_to", "g1", timeout_s=0.5, x=1.0, y=5.0)
    end, _ = sim.run("g1")
    assert end["type"] == "action_failed" and end["reason"] == "timeout after 0.5 s"
    assert abs(end["t"] - 0.5) <= 0.02
    sim.command("scout", "go_to", "g2", x=1.0, y=5.0)
    sim.step(1.0)
    evs = sim.request("cancel", id="x", robot="scout", action_id="g2")
    assert [e["type"] for e in evs] == ["action_failed", "ack"] and evs[0]["reason"] == "cancelled by x"
    before = sim.state()["robots"]["scout"]
    sim.step(1.0)
    after = sim.state()["robots"]["scout"]
    assert math.hypot(after["x"] - before["x"], after["y"] - before["y"]) < 1e-3
    assert sim.request("cancel", id="y", robot="scout", action_id="g2")[0]["field"] == "action_id"


def test_blocked_without_progress(sim: Sim) -> None:
    sim.request("place_robot", robot="robovie", x=7.0, y=1.0, heading_deg=0)
    sim.command("robovie", "go_to", "g1", x=7.9, y=1.0, stall_s=1.0)  # beyond reach: the wall stops it
    end, _ = sim.run("g1")
    assert end["type"] == "action_failed" and end["reason"] == "blocked: no progress for 1 s"


def test_stream_and_progress_events(sim: Sim) -> None:
    sim.request("stream", enabled=True, period_ms=500)
    sim.send({"id": "g", "type": "command", "robot": "scout", "action": "go_to", "args": {"x": 6.2, "y": 4.0},
              "progress_s": 1.0})
    evs = sim.step(2.0)
    assert [e["t"] for e in only(evs, "state")] == [0.5, 1.0, 1.5, 2.0]
    prog = only(evs, "action_progress", id="g")
    assert [p["elapsed_s"] for p in prog] == [1.0, 2.0]
    assert prog[0]["remaining_m"] > prog[1]["remaining_m"]
    sim.request("stream", enabled=False)
    assert not only(sim.step(1.0), "state")


def test_users_come_in_at_the_door_and_walk(sim: Sim) -> None:
    ack = sim.request("spawn_user", name="alice")[0]
    assert ack["result"]["x"] == 4.0 and ack["result"]["y"] == 0.6 and len(ack["result"]["face"]) == 16
    assert abs(sum(v * v for v in ack["result"]["face"]) - 1.0) < 1e-5
    dup = sim.request("spawn_user", name="alice")
    assert dup[0]["type"] == "error" and dup[0]["field"] == "name"
    sim.request("move_user", name="alice", x=4.0, y=1.6, speed=0.5)
    sim.step(1.0)
    mid = sim.state()["users"]["alice"]
    assert abs(mid["y"] - 1.1) < 0.02 and mid["walking"] is True
    sim.step(2.0)
    assert sim.state()["users"]["alice"]["y"] == 1.6
    sim.request("remove_user", name="alice")
    assert sim.state()["users"] == {}


def test_positions_inside_walls_or_counter_are_refused(sim: Sim) -> None:
    evs = sim.request("spawn_user", id="u", name="ghost", x=7.5, y=4.0)
    assert evs[0]["type"] == "error" and evs[0]["field"] == "x" and "counter" in evs[0]["message"]
    evs = sim.request("place_robot", id="p", robot="robovie", x=0.2, y=3.0)
    assert evs[0]["type"] == "error" and "west wall" in evs[0]["message"]
    sim.request("add_obstacle", name="crate", x=2.0, y=5.0, w=0.5, h=0.5)
    evs = sim.request("spawn_user", id="v", name="ghost", x=2.0, y=5.0)
    assert evs[0]["type"] == "error" and "crate" in evs[0]["message"]
    assert sim.request("spawn_user", id="w", name="ghost", x=2.0, y=4.3)[0]["type"] == "ack"


def test_a_number_too_big_for_a_float_is_refused_as_not_finite_not_an_internal_error(sim: Sim) -> None:
    huge = "1" + "0" * 400  # valid JSON; Python parses it as an int that no float can hold
    evs = sim.send('{"id":"h","type":"command","robot":"scout","action":"go_to","args":{"x":%s,"y":1}}' % huge)
    assert [e["type"] for e in evs] == ["error"] and evs[0]["field"] == "args.x", evs
    assert evs[0]["message"] == "request 'h': field 'args.x' must be a finite number"
    evs = sim.send('{"id":"s","type":"step","seconds":-%s}' % huge)
    assert evs[0]["field"] == "seconds" and "internal error" not in evs[0]["message"], evs


def test_a_walking_user_stops_at_a_robot_instead_of_pushing_it_through_the_wall(sim: Sim) -> None:
    sim.request("place_robot", robot="robovie", x=0.5, y=3.0)
    sim.request("place_robot", robot="aibo", x=0.5, y=1.0)
    sim.request("spawn_user", name="alice", x=1.5, y=3.0)
    sim.request("spawn_user", name="bob", x=1.5, y=1.0)
    sim.request("move_user", name="alice", x=0.31, y=3.0, speed=1.0)  # through Robovie, up to the wall
    sim.request("move_user", name="bob", x=0.31, y=1.0, speed=1.0)  # through AIBO
    sim.step(4.0)
    st = sim.state()
    for robot, user in (("robovie", "alice"), ("aibo", "bob")):
        rb, u = st["robots"][robot], st["users"][user]
        radius = json.loads(sim.lines[0])["robots"][robot]["radius_m"]
        assert rb["x"] >= radius, (robot, rb)  # still inside the room
        assert math.hypot(rb["x"] - u["x"], rb["y"] - u["y"]) >= radius + 0.25 - 0.02, (robot, rb, u)  # no overlap
        assert u["walking"] is False  # the walk ended in front of the robot


def test_a_teleport_onto_a_robot_is_refused_instead_of_shoving_the_robot(sim: Sim) -> None:
    start = sim.state()["robots"]
    evs = sim.request("place_robot", id="p", robot="aibo", x=4.0, y=3.2)  # onto Robovie
    assert evs[0]["type"] == "error" and evs[0]["field"] == "x" and "robot:robovie" in evs[0]["message"], evs
    evs = sim.request("spawn_user", id="u", name="alice", x=6.2, y=2.0)  # onto Scout
    assert evs[0]["type"] == "error" and evs[0]["field"] == "x" and "robot:scout" in evs[0]["message"], evs
    sim.request("spawn_user", name="bob", x=5.0, y=1.0)
    evs = sim.request("move_user", id="m", name="bob", x=2.5, y=2.0)  # a teleport onto AIBO
    assert evs[0]["type"] == "error" and "robot:aibo" in evs[0]["message"], evs
    evs = sim.request("place_robot", id="q", robot="pino", x=5.0, y=1.2)  # onto bob
    assert evs[0]["type"] == "error" and "user:bob" in evs[0]["message"], evs
    sim.step(1.0)
    now = sim.state()["robots"]
    assert {n: (rb["x"], rb["y"]) for n, rb in now.items()} == {n: (rb["x"], rb["y"]) for n, rb in start.items()}
    assert sim.request("place_robot", robot="robovie", x=4.05, y=3.2)[0]["type"] == "ack"  # moving over itself is fine
    assert sim.request("move_user", name="bob", x=5.0, y=1.1)[0]["type"] == "ack"


def test_a_refused_move_user_leaves_the_user_as_it_was(sim: Sim) -> None:
    sim.request("spawn_user", name="bob", x=5.0, y=1.0, heading_deg=90)
    evs = sim.request("move_user", id="m", name="bob", x=7.5, y=4.0, heading_deg=180)  # into the counter
    assert evs[0]["type"] == "error" and "counter" in evs[0]["message"], evs
    assert sim.state()["users"]["bob"]["heading_deg"] == 90.0


def test_an_obstacle_over_a_robot_or_a_user_is_refused_instead_of_trapping_it(sim: Sim) -> None:
    evs = sim.request("add_obstacle", id="o1", name="box", x=6.2, y=2.0, w=1.0, h=1.0)  # around Scout
    assert evs[0]["type"] == "error" and evs[0]["field"] == "x" and "robot:scout" in evs[0]["message"], evs
    evs = sim.request("add_obstacle", id="o2", name="box", x=6.45, y=2.0, w=0.2, h=0.2)  # 5 cm into Scout
    assert evs[0]["type"] == "error" and "robot:scout" in evs[0]["message"], evs
    sim.request("spawn_user", name="al", x=2.0, y=5.0)
    evs = sim.request("add_obstacle", id="o3", name="box", x=2.0, y=5.3, w=1.0, h=0.2)
    assert evs[0]["type"] == "error" and "user:al" in evs[0]["message"], evs
    assert sim.state()["obstacles"] == {}
    sim.command("scout", "go_to", "g", x=5.0, y=2.0)
    assert sim.run("g")[0]["type"] == "action_ended"
    assert sim.request("add_obstacle", id="o4", name="box", x=6.2, y=2.0, w=0.5, h=0.5)[0]["type"] == "ack"  # Scout left


def test_a_walking_user_stops_at_an_obstacle_or_the_counter_instead_of_walking_through(sim: Sim) -> None:
    sim.request("add_obstacle", name="crate", x=2.0, y=5.0, w=0.4, h=0.6)
    sim.request("spawn_user", name="al", x=1.0, y=5.0, heading_deg=0)
    sim.request("move_user", name="al", x=3.0, y=5.0, speed=1.0)  # straight through the crate
    sim.request("spawn_user", name="bo", x=6.7, y=2.0, heading_deg=90)
    sim.request("move_user", name="bo", x=6.7, y=5.0, speed=1.0)  # clear of the counter (x >= 7.2): walks on
    sim.step(4.0)
    users = sim.state()["users"]
    assert users["al"]["walking"] is False
    assert 1.5 <= users["al"]["x"] <= 1.8 - 0.25 + 0.01 + 0.02, users["al"]  # just short of the crate's west face
    assert (users["bo"]["x"], users["bo"]["y"]) == (6.7, 5.0)



def test_a_request_longer_than_the_line_limit_is_refused_naming_its_length_and_the_limit(sim: Sim) -> None:
    line = json.dumps({"id": "big", "type": "add_obstacle", "name": "x" * 10_000_000, "x": 1.0, "y": 5.0, "w": 0.2,
                       "h": 0.2})
    evs = sim.send(line)
    assert [e["type"] for e in evs] == ["error"]
    assert evs[0]["id"] == "big" and evs[0]["field"] is None
    assert evs[0]["message"] == (f"request 'big': is a line of {len(line)} characters, longer than the protocol's limit "
                                 "of 10000000 characters; it was not handled")
    assert not sim.world.obstacles
    assert sim.step(0.5)[-1]["type"] == "ack"  # still working


def test_an_event_longer_than_the_line_limit_becomes_an_error_naming_its_length_and_the_limit(sim: Sim) -> None:
    for i in range(3):  # each request within the limit, the world state holding all three names beyond it
        assert sim.request("add_obstacle", name=str(i) * 4_000_000, x=1.0 + i, y=5.0, w=0.2, h=0.2)[0]["type"] == "ack"
    evs = sim.request("query", id="q")
    assert [e["type"] for e in evs] == ["ack", "error"]
    assert evs[1]["id"] == "q" and evs[1]["field"] is None
    assert re.fullmatch(r"request 'q': its state event would be a line of 12\d{6} characters, longer than the "
                        r"protocol's limit of 10000000 characters; it was not sent", evs[1]["message"]), evs[1]
    assert sim.step(0.5)[-1]["type"] == "ack"  # still working
