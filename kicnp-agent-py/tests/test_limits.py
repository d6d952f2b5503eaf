"""The members the gateway holds to 256 characters (docs/protocol.md: names, actions, ids, subjects, class names) are
refused by the SDK before anything is sent, with a ValueError naming the argument; at the limit they go on to be sent.
No gateway is needed: the agent is never started, so a call that passes the checks fails for want of a connection."""
import re
import unittest

from fake_gateway import FakeGateway
from harness import eventually
from kicnp_agent import Agent, NotConnectedError

LONG = "n" * 257
LONGEST = "n" * 256


def refusal(argument, method, length=257):
    return ("The argument '%s' of %s is %d characters long; the server allows at most 256, so nothing was sent."
            % (argument, method, length))


class LimitsTest(unittest.TestCase):

    def setUp(self):
        self.agent = Agent("pyuser", "t", kind="user")
        self.addCleanup(self.agent.close)

    def test_eachLimitedArgumentOverTheLimit_isAValueErrorNamingIt_beforeAnythingIsSent(self):
        a = self.agent
        cases = [(lambda: a.sensor(LONG, 1), "sensor", "sensor"),
                 (lambda: a.query(LONG), "of_class", "query"),
                 (lambda: a.prove(LONG), "of_class", "prove"),
                 (lambda: a.subscribe(LONG), "of_class", "subscribe"),
                 (lambda: a.unsubscribe(LONG), "of_class", "unsubscribe"),
                 (lambda: a.relay_to(LONG, "s", "b"), "agent", "relay_to"),
                 (lambda: a.relay_to("bob", LONG, "b"), "subject", "relay_to"),
                 (lambda: a.relay_to_kind("robot", LONG, "b"), "subject", "relay_to_kind"),
                 (lambda: a.tell_to(LONG, "s", "b"), "agent", "tell_to"),
                 (lambda: a.tell_to("bob", LONG, "b"), "subject", "tell_to"),
                 (lambda: a.tell_to_kind("robot", LONG, "b"), "subject", "tell_to_kind"),
                 (lambda: a.command(LONG, "fetch"), "robot", "command"),
                 (lambda: a.command("scout", LONG), "action", "command"),
                 (lambda: a.cancel(LONG, "c-1"), "robot", "cancel"),
                 (lambda: a.cancel("scout", LONG), "command_id", "cancel")]
        for call, argument, method in cases:
            with self.subTest(method=method, argument=argument):
                with self.assertRaises(ValueError) as refused:
                    call()
                self.assertEqual(refusal(argument, method), str(refused.exception))

    def test_atTheLimit_andForMembersWithoutOne_theCallGoesOnToSend(self):
        a = self.agent
        for call in (lambda: a.sensor(LONGEST, "v" * 1000), lambda: a.query(LONGEST),
                     lambda: a.relay_to(LONGEST, LONGEST, "b" * 1000), lambda: a.tell_to_kind("robot", LONGEST, "b"),
                     lambda: a.command("scout", LONGEST, {"k" * 1000: "v" * 1000}), lambda: a.cancel(LONGEST, LONGEST),
                     lambda: a.ask(LONG, LONG), lambda: a.destroy(LONG)):
            with self.assertRaises(NotConnectedError):
                call()

    def test_anAgentNameOverTheLimit_isRefusedWhenTheAgentIsMade(self):
        with self.assertRaises(ValueError) as refused:
            Agent(LONG, "t")
        self.assertEqual(refusal("name", "AgentOptions"), str(refused.exception))

    def test_charactersAreCountedAsTheServerCountsThem_oneBeyondTheBasicPlaneAsTwo(self):
        with self.assertRaises(ValueError) as refused:
            self.agent.relay_to("bob", "\U0001F600" * 129, "b")
        self.assertEqual(refusal("subject", "relay_to", 258), str(refused.exception))
        with self.assertRaises(NotConnectedError):
            self.agent.relay_to("bob", "\U0001F600" * 128, "b")

    def test_aCommandOfAnAgentWithTheLongestName_hasAnIdWithinTheLimit_andIsSent(self):
        server = FakeGateway(lambda gateway, m: gateway.send({"type": "ack", "id": m["id"]}))
        self.addCleanup(server.close)
        agent = Agent(LONGEST, "t", kind="user", port=server.port)
        self.addCleanup(agent.close)
        agent.start_and_wait(5)

        ticket = agent.command("scout", "fetch")

        eventually("the command is sent", lambda: any(m["type"] == "command" for m in server.received))
        self.assertEqual([ticket.command.id], [m["id"] for m in server.received if m["type"] == "command"])
        self.assertEqual(256, len(ticket.command.id))
        self.assertRegex(ticket.command.id, re.compile(r"n+-[0-9a-z]+-[0-9]+\Z"))


if __name__ == "__main__":
    unittest.main()
