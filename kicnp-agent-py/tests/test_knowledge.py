"""The knowledge base through a real gateway: query, ask, assert, destroy, subscribe, and prove/why/why_not."""
import threading
import time
import unittest

from harness import GatewayTestCase, eventually
from kicnp_agent import Ref, RequestRefusedError, frame_xml


class KnowledgeTest(GatewayTestCase):

    def setUp(self):
        super().setUp()
        self.user = self.connect("pyuser").start_and_wait(10)

    def test_query_returnsTheInstancesAsFrames_withTypedValues(self):
        cups = {f.name: f for f in self.user.query("Cup")}  # cup1, and what other tests put
        self.assertIn("cup1", cups)
        self.assertEqual(("Cup", True), (cups["cup1"].isa, cups["cup1"].is_instance))
        self.assertEqual({"ml": 250, "colour": "blue"}, cups["cup1"].slots)

    def test_snapshot_isTheQuerysFrames_withTheServersClockWhenItReadThem(self):
        before = int(time.time() * 1000)
        snapshot = self.user.snapshot("Cup")
        after = int(time.time() * 1000)
        self.assertIn("cup1", [f.name for f in snapshot.frames])
        # The test's gateway runs on this machine, so its clock is this one's.
        self.assertIsInstance(snapshot.server_time, int)
        self.assertTrue(before <= snapshot.server_time <= after, (before, snapshot.server_time, after))

    def test_ask_givesTheSlotsValue_noneWithoutOne_andARefusalNamingTheRequest(self):
        self.assertEqual(250, self.user.ask("cup1", "ml"))
        self.assertIsNone(self.user.ask("cup1", "owner"))
        with self.assertRaises(RequestRefusedError) as refused:
            self.user.ask("cup1", "handle")
        self.assertEqual("rejected", refused.exception.code)
        self.assertTrue(str(refused.exception).startswith(
            "The server refused the ask for slot 'handle' of frame 'cup1' (rejected): "), str(refused.exception))

    def test_assertAndDestroy_changeTheGatewaysKnowledgeBase(self):
        self.user.assert_frames(frame_xml("cup2", "Cup", instance=True, slots={"ml": 100, "colour": " red "}))
        self.assertTrue(self.gateway.call("contains", frame="cup2")["contains"])
        self.assertEqual(" red ", self.gateway.call("value", frame="cup2", slot="colour")["value"])
        self.user.destroy("cup2")
        self.assertFalse(self.gateway.call("contains", frame="cup2")["contains"])
        with self.assertRaises(RequestRefusedError) as refused:
            self.user.assert_frames(frame_xml("mug", "Mug", instance=True))
        self.assertEqual("rejected", refused.exception.code)
        self.assertIn("the assert of 1 frame(s)", str(refused.exception))
        self.assertIn("Mug", str(refused.exception))

    def test_subscribe_deliversEachChangeToTheCallback(self):
        changes = []
        self.user.subscribe("Cup", changes.append)
        self.user.assert_frames(frame_xml("cup3", "Cup", instance=True, slots={"ml": 90}))
        self.user.destroy("cup3")
        eventually("the user hears cup3 come and go", lambda: len(changes) == 2)
        self.assertEqual([("Cup", "added", "cup3"), ("Cup", "removed", "cup3")],
                         [(c.of_class, c.change, c.name) for c in changes])
        self.assertIn("<NAME>cup3</NAME>", changes[0].frame)
        self.assertIsNone(changes[1].frame)
        self.user.unsubscribe("Cup")
        with self.assertRaises(RequestRefusedError) as refused:
            self.user.subscribe("cup1")
        self.assertEqual("rejected", refused.exception.code)

    def test_proveWhyAndWhyNot_readTheEnginesAnswers(self):
        proofs = self.user.prove("Cup")
        self.assertEqual(1, len(proofs))
        self.assertEqual(("Cup", None, ("js: s.ml > 0",)), (proofs[0].of_class, proofs[0].instance, proofs[0].assumptions))
        self.assertEqual(("User", "ken"), (proofs[0].slots["owner"].of_class, proofs[0].slots["owner"].instance))
        reason = self.user.why("cup1")
        self.assertEqual(("cup1", "Cup", True, {"source": "signal_pyrobot_sonar"}, ("value: > = 0.5",)),
                         (reason.instance, reason.of_class, reason.derived, reason.binding, reason.conditions))
        self.assertEqual("signal_pyrobot_sonar", reason.supports[0].instance)
        not_fired = self.user.why_not("Cup", {"mUser": "ken"})
        self.assertEqual("No User is known yet.", not_fired.summary)
        self.assertEqual(("mUser", "KnownUser", 0), (not_fired.slots[0].slot, not_fired.slots[0].argument,
                                                     not_fired.slots[0].candidate_count))
        self.assertEqual(("waiting", {"mUser": "ken"}), (not_fired.bindings[0].outcome, not_fired.bindings[0].binding))
        with self.assertRaises(RequestRefusedError) as refused:
            self.user.prove("SensorSignal")
        self.assertIn("the proof of class 'SensorSignal'", str(refused.exception))
        self.assertIn("Only Cup can be proved here.", str(refused.exception))

    def test_requestsFromManyThreadsAtOnce_eachGetTheirOwnAnswer(self):
        answers, errors = [], []

        def ask_many():
            try:
                for _ in range(20):
                    answers.append((self.user.ask("cup1", "ml"), self.user.ask("cup1", "colour")))
            except Exception as e:  # kept for the assertion below, which names it
                errors.append(e)

        threads = [threading.Thread(target=ask_many) for _ in range(8)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join(30)
        self.assertEqual([], errors)
        self.assertEqual([(250, "blue")] * 160, answers)


class PeerTest(GatewayTestCase):

    def test_aPeerPushesFramesAllOrNone_andPullsASubtreeParentsFirst(self):
        peer = self.connect("pypeer").start_and_wait(10)
        peer.push(frame_xml("Mug", "Cup", slots={"handle": True}), frame_xml("mug1", "Mug", instance=True))
        self.assertTrue(self.gateway.call("contains", frame="mug1")["contains"])
        names = [f.name for f in peer.pull("Cup")]
        self.assertEqual("Cup", names[0])
        self.assertLess(names.index("Mug"), names.index("mug1"))
        self.assertIn("cup1", names)
        with self.assertRaises(RequestRefusedError) as refused:
            peer.push(frame_xml("Tumbler", "Cup"), frame_xml("Flute", "NoSuchGlass"))
        self.assertEqual("rejected", refused.exception.code)
        self.assertIn("The server refused the push of 2 frame(s) (rejected): ", str(refused.exception))
        self.assertFalse(self.gateway.call("contains", frame="Tumbler")["contains"])

    def test_aUserMayNotPush(self):
        user = self.connect("pyuser").start_and_wait(10)
        with self.assertRaises(RequestRefusedError) as refused:
            user.push(frame_xml("Mug", "Cup"))
        self.assertEqual("forbidden", refused.exception.code)


class SensorSignalTest(GatewayTestCase):

    def test_sensorWithTtl_isInTheKnowledgeBaseWithItsExpiry_andGoesWhenItRunsOut(self):
        robot = self.connect("pyrobot").start_and_wait(10)
        robot.sensor("battery", 0.87, Ref("agent_pyrobot"), ttl=60)
        eventually("the battery signal is in", lambda: self.gateway.call("contains", frame="signal_pyrobot_battery")
                   ["contains"])
        values = self.gateway.call("value", frame="signal_pyrobot_battery", slot="values")["value"]
        self.assertEqual([0.87, {"ref": "agent_pyrobot"}], values)
        time = self.gateway.call("value", frame="signal_pyrobot_battery", slot="time")["value"]
        expires = self.gateway.call("value", frame="signal_pyrobot_battery", slot="expires")["value"]
        self.assertEqual(60000, expires - time)

        robot.sensor("bump", True, ttl=0.3)
        eventually("the bump signal is in", lambda: self.gateway.call("contains", frame="signal_pyrobot_bump")["contains"])
        eventually("the bump signal expires", lambda: not self.gateway.call("contains", frame="signal_pyrobot_bump")
                   ["contains"], timeout=5)
        self.assertTrue(self.gateway.call("contains", frame="signal_pyrobot_battery")["contains"])

    def test_subscribersHearASignalsValuesTyped(self):
        user = self.connect("pyuser").start_and_wait(10)
        robot = self.connect("pyrobot").start_and_wait(10)
        changes = []
        user.subscribe("SensorSignal", changes.append)
        robot.sensor("sonar", 1.5, 7, "near", [0.25, False])
        eventually("the user hears the sonar", lambda: any(c.name == "signal_pyrobot_sonar" for c in changes))
        sonar = [c for c in changes if c.name == "signal_pyrobot_sonar"][0]
        self.assertEqual("added", sonar.change)
        self.assertEqual([1.5, 7, "near", [0.25, False]], sonar.values)


if __name__ == "__main__":
    unittest.main()
