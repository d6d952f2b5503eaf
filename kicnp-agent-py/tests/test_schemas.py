"""Every message the SDK sends conforms to its published schema (docs/protocol/schemas/TYPE.json): an agent drives
each call against a stand-in gateway that answers as a gateway would and keeps what it receives."""
import json
import pathlib
import unittest

from fake_gateway import FakeGateway
from harness import eventually
from kicnp_agent import Agent, Ref, frame_xml
from schema_check import problems

SCHEMAS = pathlib.Path(__file__).resolve().parent.parent.parent / "docs" / "protocol" / "schemas"
REASON = {"instance": "cup1", "ofClass": "Cup", "derived": False, "binding": {}, "conditions": [], "supports": []}
ANSWERS = {"query": {"type": "frames", "frames": []},
           "ask": {"type": "answer"}, "prove": {"type": "proofs", "proofs": []},
           "why": {"type": "explained", "reason": REASON},
           "why_not": {"type": "not_fired", "frame": "Cup", "summary": "It has.", "slots": [], "bindings": [],
                       "truncated": False}}
ACKED = {"assert", "destroy", "subscribe", "unsubscribe", "command", "cancel", "relay"}


def schema(kind):
    return json.loads((SCHEMAS / (kind + ".json")).read_text(encoding="utf-8"))


def answer_as_a_gateway(gateway, message):
    kind = message["type"]
    if kind in ANSWERS:
        gateway.send(dict(ANSWERS[kind], id=message["id"]))
    elif kind in ACKED and message["id"]:
        gateway.send({"type": "ack", "id": message["id"]})


class SchemaTest(unittest.TestCase):

    def test_theCheckerFindsWhatBreaksASchema(self):
        self.assertEqual([], problems({"v": 1, "type": "heartbeat", "time": 5}, schema("heartbeat")))
        self.assertEqual(["$.time is 5.5, not of type integer"],
                         problems({"v": 1, "type": "heartbeat", "time": 5.5}, schema("heartbeat")))
        self.assertEqual(["$ lacks 'detail'", "$.stage is 'done', not one of ['started', 'progress', 'ended', 'failed']"],
                         sorted(problems({"v": 1, "type": "feedback", "id": "c", "robot": "r", "stage": "done"},
                                         schema("feedback"))))
        self.assertEqual(["$ matches 2 of the oneOf schemas, not exactly 1"],
                         problems({"v": 1, "type": "relay", "id": "", "from": "a", "toAgent": "b", "toKind": "robot",
                                   "subject": "s", "body": "b"}, schema("relay")))
        self.assertEqual(["$.subject is 257 characters long, more than 256"],
                         problems({"v": 1, "type": "relay", "id": "", "from": "a", "toAgent": "b", "subject": "s" * 257,
                                   "body": "b" * 257}, schema("relay")))
        self.assertEqual(["$.values[0] matches 0 of the oneOf schemas, not exactly 1"],
                         problems({"v": 1, "type": "sensor", "source": "a", "sensor": "s", "values": [{"x": 1}]},
                                  schema("sensor")))

    def test_theTaggedFormOfAFloatJsonHasNoNumberFor_isAPublishedValue(self):
        answer = {"v": 1, "type": "answer", "id": "q", "value": [{"float": "NaN"}, {"float": "-Infinity"}]}
        self.assertEqual([], problems(answer, schema("answer")))
        self.assertEqual(["$.value matches 0 of the oneOf schemas, not exactly 1"],
                         problems(dict(answer, value=[{"float": "nan"}]), schema("answer")))

    def test_everyMessageTheSdkSends_conformsToItsSchema(self):
        server = FakeGateway(answer_as_a_gateway)
        self.addCleanup(server.close)
        agent = Agent("scout", "t", port=server.port, heartbeat_interval=0.05, capabilities=[frame_xml("Fetch")])
        self.addCleanup(agent.close)

        @agent.action("wave")
        def wave(command, handle):
            handle.progress(0.5, "halfway")
            return "waved"

        @agent.action("grab")
        def grab(command, handle):
            raise ValueError("no arm")

        agent.start_and_wait(5)
        server.send({"type": "command", "id": "c1", "robot": "scout", "action": "wave", "args": {"n": "1"}})
        with self.assertLogs("kicnp_agent", "WARNING"):  # the log line of the handler that raises, kept out of the output
            server.send({"type": "command", "id": "c2", "robot": "scout", "action": "grab", "args": {}})
            eventually("c2 fails", lambda: any(m["type"] == "feedback" and m["id"] == "c2" and m["stage"] == "failed"
                                               for m in server.received))
        agent.sensor("sonar", 1.5, 7, True, "near", Ref("ken"), [0.1, [2]], ttl=0.5)
        agent.query("Cup")
        agent.ask("cup1", "ml")
        agent.prove("Cup", {"owner": "ken"})
        agent.why("cup1")
        agent.why_not("Cup")
        agent.assert_frames(frame_xml("cup2", "Cup", instance=True, slots={"ml": 1}), frame_xml("cup3", "Cup", True))
        agent.destroy("cup2")
        agent.subscribe("Cup")
        agent.unsubscribe("Cup")
        agent.relay_to("alice", "say", "hi")
        agent.tell_to_kind("user", "say", "hi all")
        ticket = agent.command("pino", "walk", {"steps": 3})
        agent.cancel("pino", ticket.command.id, "enough")
        eventually("both commands end and a heartbeat goes out", lambda: {"c1", "c2"} <= {
            m["id"] for m in server.received if m["type"] == "feedback" and m["stage"] in ("ended", "failed")}
            and any(m["type"] == "heartbeat" for m in server.received))

        sent = list(server.received)
        self.assertEqual({"hello", "register", "heartbeat", "sensor", "feedback", "query", "ask", "prove", "why",
                          "why_not", "assert", "destroy", "subscribe", "unsubscribe", "relay", "command", "cancel"},
                         {m["type"] for m in sent})
        for message in sent:
            self.assertEqual([], problems(message, schema(message["type"])), message)
        self.assertEqual([("started", None), ("progress", 0.5), ("ended", None)],
                         [(m["stage"], m.get("progress")) for m in sent if m["type"] == "feedback" and m["id"] == "c1"])


if __name__ == "__main__":
    unittest.main()
