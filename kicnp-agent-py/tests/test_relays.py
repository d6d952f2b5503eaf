"""Relays between agents through a real gateway: waiting for the hub's ack, fire and forget, and refusals."""
import queue
import unittest

from harness import GatewayTestCase, eventually
from kicnp_agent import RequestRefusedError


class RelayTest(GatewayTestCase):

    def test_relaysReachTheAgentNamed_andEveryAgentOfAKind(self):
        robot = self.connect("pyrobot")
        heard = queue.Queue()
        robot.on_relay = heard.put
        robot.start_and_wait(10)
        user = self.connect("pyuser").start_and_wait(10)

        user.relay_to("pyrobot", "say", "hello")
        user.tell_to("pyrobot", "say", "quickly")
        user.relay_to_kind("robot", "all", "stop")
        relays = [heard.get(timeout=10) for _ in range(3)]
        self.assertEqual([("pyuser", "say", "hello", "pyrobot", None), ("pyuser", "say", "quickly", "pyrobot", None),
                          ("pyuser", "all", "stop", None, "robot")],
                         [(r.sender, r.subject, r.body, r.to_agent, r.to_kind) for r in relays])

    def test_relayToAnAgentNotConnected_isRefusedNamingIt(self):
        user = self.connect("pyuser").start_and_wait(10)
        with self.assertRaises(RequestRefusedError) as refused:
            user.relay_to("pyrobot2", "say", "hello")
        self.assertEqual("unknown_agent", refused.exception.code)
        self.assertTrue(str(refused.exception).startswith(
            "The server refused the relay to agent 'pyrobot2' (unknown_agent): "), str(refused.exception))

    def test_aFireAndForgetRelayToAnAgentNotConnected_isRefusedLater_inTheLog(self):
        user = self.connect("pyuser").start_and_wait(10)
        with self.assertLogs("kicnp_agent", "WARNING") as logged:
            user.tell_to("pyrobot2", "say", "hello")
            eventually("the refusal comes", lambda: logged.records)
        self.assertEqual(["Agent 'pyuser': the server says unknown_agent: No agent 'pyrobot2' is registered."],
                         [r.getMessage() for r in logged.records])
        self.assertTrue(user.is_connected)


if __name__ == "__main__":
    unittest.main()
