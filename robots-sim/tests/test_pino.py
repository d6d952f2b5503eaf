"""PINO: slow walking to a user and shaking hands; stumbling on collisions."""

from __future__ import annotations

from conftest import Sim, only


def test_pino_walks_to_user_and_shakes_hands(sim: Sim) -> None:
    # PINO is at (2.5, 3.8); alice stands 1.5 m south of it.
    sim.request("spawn_user", name="alice", x=2.5, y=1.6, heading_deg=90)
    far = sim.command("pino", "shake_hands", "k0", user="alice")
    assert "m away" in only(far, "action_failed", id="k0")[0]["reason"]
    sim.command("pino", "approach_user", "a1", user="alice")
    end, seen = sim.run("a1", max_s=40)
    assert end["type"] == "action_ended", end
    assert end["t"] >= (1.27 - 0.1) / 0.25  # walked ~1.27 m (less the tolerance) at no more than 0.25 m/s
    speeds = [e for e in seen if e["type"] == "state"]
    assert not speeds or max(s["robots"]["pino"]["v_mps"] for s in speeds) <= 0.25
    sim.command("pino", "shake_hands", "k1", user="alice")
    end, _ = sim.run("k1")
    assert end["type"] == "action_ended" and end["result"]["user"] == "alice" and end["result"]["duration_s"] == 2.0
    assert sim.state()["robots"]["pino"]["fallen"] is False


def test_pino_speed_is_limited(sim: Sim) -> None:
    sim.request("stream", enabled=True, period_ms=100)
    sim.command("pino", "go_to", "g1", x=1.5, y=1.0)
    end, seen = sim.run("g1", max_s=40)
    assert end["type"] == "action_ended"
    vs = [s["robots"]["pino"]["v_mps"] for s in only(seen, "state")]
    assert max(vs) == 0.25


def test_pino_stumbles_when_walking_into_an_obstacle(sim: Sim) -> None:
    sim.request("add_obstacle", name="chair", x=2.5, y=2.8, w=0.6, h=0.3)
    sim.command("pino", "go_to", "g1", x=2.5, y=1.5)
    end, seen = sim.run("g1", max_s=30)
    assert end["type"] == "action_failed" and end["reason"] == "stumbled"
    assert only(seen, "sensor", robot="pino", sensor="fall")[0]["contact"] == "chair"
    assert sim.state()["robots"]["pino"]["fallen"] is True
    again = sim.command("pino", "go_to", "g2", x=1.5, y=3.8)
    assert only(again, "action_failed", id="g2")[0]["reason"] == "fallen: stand_up first"
    sim.command("pino", "stand_up", "u1")
    end, _ = sim.run("u1")
    assert end["type"] == "action_ended" and end["result"]["duration_s"] == 3.0
    sim.command("pino", "go_to", "g3", x=1.5, y=3.8)
    assert sim.run("g3", max_s=30)[0]["type"] == "action_ended"


def test_a_handshake_with_a_user_who_leaves_the_room_fails_saying_the_user_left(sim: Sim) -> None:
    sim.request("spawn_user", name="alice", x=2.5, y=3.1, heading_deg=90)  # 0.27 m from PINO's body
    sim.command("pino", "shake_hands", "k1", user="alice")
    sim.step(0.5)
    sim.request("remove_user", name="alice")
    end, _ = sim.run("k1")
    assert end["type"] == "action_failed" and end["reason"] == "user 'alice' left", end
