"""Robovie: eye cameras (face_seen / face_lost), head pan, speech timing, hand shaking."""

from __future__ import annotations

from conftest import Sim, cosine, only


def faces(events: list[dict], kind: str) -> dict[str, dict]:
    return {e["truth_user"]: e for e in only(events, "sensor", robot="robovie", sensor=kind)}


def test_robovie_sees_user_in_front_not_behind_and_loses_them(sim: Sim) -> None:
    # Robovie stands at (4.0, 3.2) facing south (-90 degrees).
    ack = sim.request("spawn_user", name="alice", x=4.0, y=2.0, heading_deg=90)
    face = ack[0]["result"]["face"]
    sim.request("spawn_user", name="bob", x=4.0, y=4.5, heading_deg=-90)
    seen = faces(sim.step(0.2), "face_seen")
    assert set(seen) == {"alice"}
    a = seen["alice"]
    assert abs(a["bearing_deg"]) < 1.0 and abs(a["distance_m"] - 1.2) < 0.01
    assert len(a["face"]) == 16 and a["face"] != face  # noisy, but close to the true face
    assert cosine(a["face"], face) > 0.9
    assert [f["truth_user"] for f in sim.state()["robots"]["robovie"]["faces_in_view"]] == ["alice"]
    assert not faces(sim.step(1.0), "face_seen")  # no repeats while alice stays in view
    sim.request("move_user", name="alice", x=1.0, y=2.0)  # far to Robovie's right, out of view
    lost = faces(sim.step(0.1), "face_lost")
    assert set(lost) == {"alice"} and lost["alice"]["track"] == a["track"]


def test_face_hidden_behind_another_user_or_out_of_range(sim: Sim) -> None:
    sim.request("spawn_user", name="near", x=4.0, y=2.2, heading_deg=90)
    sim.request("spawn_user", name="hidden", x=4.0, y=1.2, heading_deg=90)
    sim.request("spawn_user", name="far", x=4.6, y=0.15, heading_deg=90)
    assert set(faces(sim.step(0.2), "face_seen")) == {"near"}


def test_head_pan_brings_side_user_into_view(sim: Sim) -> None:
    sim.request("spawn_user", name="carol", x=5.5, y=3.2, heading_deg=180)  # east of Robovie: 90 deg left of its heading
    assert not faces(sim.step(0.2), "face_seen")
    sim.command("robovie", "head", "h1", pan_deg=90)
    end, seen = sim.run("h1")
    assert end["type"] == "action_ended" and end["result"]["duration_s"] == 1.0
    assert "carol" in faces(seen, "face_seen")


def test_say_utterance_duration_is_proportional_to_length(sim: Sim) -> None:
    text = "How are you! I have never seen you before. What is your name?"
    evs = sim.command("robovie", "say", "s1", text=text)
    utt = only(evs, "utterance")
    assert len(utt) == 1 and utt[0]["text"] == text and utt[0]["robot"] == "robovie"
    assert utt[0]["duration_s"] == round(0.06 * len(text), 3)
    end, _ = sim.run("s1")
    assert end["type"] == "action_ended"
    assert abs((end["t"] - utt[0]["t"]) - 0.06 * len(text)) <= 1 / 60 + 1e-6
    short = only(sim.command("robovie", "say", "s2", text="Hi"), "utterance")
    assert short[0]["duration_s"] == 0.5  # the minimum
    end2, _ = sim.run("s2")
    assert end2["type"] == "action_ended"
    assert abs((end2["t"] - short[0]["t"]) - 0.5) <= 1 / 60 + 1e-6


def test_busy_speech_is_refused_with_an_error(sim: Sim) -> None:
    sim.command("robovie", "say", "s1", text="A fairly long sentence to keep the speaker busy.")
    evs = sim.command("robovie", "say", "s2", text="Interrupting")
    assert [e["type"] for e in evs] == ["error"]
    assert evs[0]["id"] == "s2" and "busy" in evs[0]["message"] and "s1" in evs[0]["message"]
    arms = sim.command("robovie", "move_arms", "m1", pose="wave")  # other parts stay free
    assert [e["type"] for e in arms] == ["ack", "action_started"]


def test_robovie_shakes_both_hands_with_near_user(sim: Sim) -> None:
    sim.request("spawn_user", name="alice", x=4.0, y=2.4, heading_deg=90)
    sim.command("robovie", "shake_hands", "k1", user="alice")
    assert sim.state()["robots"]["robovie"]["arms"] == {"left": "shake", "right": "shake"}
    end, _ = sim.run("k1")
    assert end["type"] == "action_ended" and end["result"]["duration_s"] == 2.0
    assert sim.state()["robots"]["robovie"]["arms"] == {"left": "down", "right": "down"}


def test_audio_dir_is_optional(tmp_path) -> None:
    """With --audio-dir, say writes a WAV where espeak-ng exists and is skipped cleanly where not."""
    import shutil

    from kicnp_sim.audio import Speaker
    from kicnp_sim.protocol import Dispatcher

    sim = Sim()
    speaker = Speaker(str(tmp_path))
    sim.world.audio = speaker
    sim.disp = Dispatcher(sim.world, manual=True, time_scale=1.0)
    utt = only(sim.command("robovie", "say", "s1", text="Welcome to my room."), "utterance")[0]
    assert sim.run("s1")[0]["type"] == "action_ended"
    speaker.close()
    if shutil.which("espeak-ng") is None:
        assert "audio_file" not in utt
    else:
        assert utt["audio_file"].endswith("robovie-s1.wav")
        assert (tmp_path / "robovie-s1.wav").stat().st_size > 44
