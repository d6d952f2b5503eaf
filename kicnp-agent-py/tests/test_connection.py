"""The connection's life against a real gateway: refusal, heartbeats, being dropped, and a server restart."""
import time
import unittest

from harness import GatewayTestCase, eventually
from kicnp_agent import Agent, AuthenticationError, frame_xml


class Counting(Agent):
    """An agent that counts its registrations and losses."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.connected = 0
        self.disconnected = []

    def on_connected(self):
        self.connected += 1

    def on_disconnected(self, reason):
        self.disconnected.append(reason)


class ConnectionTest(GatewayTestCase):

    def test_wrongToken_stopsTheAgentWithTheServersReason(self):
        agent = self.connect("pyrobot", token="not-the-token")
        with self.assertRaises(AuthenticationError) as refused:
            agent.start_and_wait(10)
        self.assertTrue(str(refused.exception).startswith("The server refused agent 'pyrobot' (kind robot): "),
                        str(refused.exception))
        self.assertIs(refused.exception, agent.stopped)
        self.assertFalse(agent.is_connected)

    def test_capabilitiesTheServerRefuses_stopTheAgentNamingTheProblem(self):
        agent = self.connect("pyrobot", capabilities=[frame_xml("Fly", "NoSuchAction")])
        with self.assertRaises(AuthenticationError) as refused:
            agent.start_and_wait(10)
        self.assertTrue(str(refused.exception).startswith("The server refused to register agent 'pyrobot' (rejected): "),
                        str(refused.exception))
        self.assertIn("NoSuchAction", str(refused.exception))

    def test_aSecondConnectionUnderTheSameName_replacesTheFirst_whichStops(self):
        first = self.connect("pyrobot").start_and_wait(10)
        with self.assertLogs("kicnp_agent", "ERROR") as logged:
            self.connect("pyrobot").start_and_wait(10)
            eventually("the first stops", lambda: first.stopped is not None)
        self.assertIsInstance(first.stopped, AuthenticationError)
        self.assertTrue(str(first.stopped).startswith("Agent 'pyrobot' was replaced by a newer connection under its "
                                                      "name: "), str(first.stopped))
        self.assertIn("%s The agent stops." % first.stopped, [r.getMessage() for r in logged.records])
        self.assertFalse(first.is_connected)

    def test_heartbeats_keepAnIdleAgentConnectedPastTheServersTimeout(self):
        agent = self.connect("pyrobot", Counting).start_and_wait(10)
        time.sleep(4.5)  # the gateway drops an agent it has not heard for 3 s
        self.assertEqual(([], 1), (agent.disconnected, agent.connected))
        self.assertIn("pyrobot", self.gateway.call("agents")["agents"])

    def test_agentTheServerDrops_reconnectsAndRegistersAgain(self):
        agent = self.connect("pyrobot", Counting, heartbeat_interval=30).start_and_wait(10)
        with self.assertLogs("kicnp_agent", "WARNING") as logged:
            eventually("the gateway drops the silent agent", lambda: agent.disconnected, timeout=10)
        self.assertTrue(any(r.getMessage().startswith("Agent 'pyrobot': the server says heartbeat_timeout: ")
                            for r in logged.records), logged.output)
        eventually("the agent is registered again", lambda: agent.connected == 2 and agent.is_connected)
        self.assertIn("pyrobot", self.gateway.call("agents")["agents"])

    def test_serverRestart_reRegistersResubscribesAndTakesCommandsAgain(self):
        robot = self.connect("pyrobot", Counting)

        @robot.action("wave")
        def wave(command, handle):
            return "waved %s times" % command.args["times"]

        robot.start_and_wait(10)
        user = self.connect("pyuser", Counting).start_and_wait(10)
        changes = []
        user.subscribe("Cup", changes.append)

        self.gateway.call("restart")
        eventually("both agents are registered with the new server",
                   lambda: robot.connected == 2 and user.connected == 2 and robot.is_connected and user.is_connected)
        eventually("the new server has both", lambda: {"pyrobot", "pyuser"} <= set(self.gateway.call("agents")["agents"]))
        self.assertEqual((["connection lost"], ["connection lost"]), (robot.disconnected, user.disconnected))

        # Putting cup4 until the user hears of it: the renewed subscription may be a moment behind the registration.
        ml = iter(range(1, 1000))
        eventually("the renewed subscription delivers", lambda: self.gateway.call(
            "put", xml="<FRAME><NAME>cup4</NAME><ISA>Cup</ISA><ISINSTANCE>TRUE</ISINSTANCE><SLOTLIST><SLOT><NAME>ml"
                       "</NAME><VALUE>%d</VALUE></SLOT></SLOTLIST></FRAME>" % next(ml)) and changes)
        self.assertEqual("cup4", changes[0].name)

        self.gateway.call("command", id="py-after-restart", robot="pyrobot", action="wave", args={"times": "1"})
        eventually("the new server hears the command end", lambda: self.gateway.heard("py-after-restart")
                   == ["started py-after-restart", "ended py-after-restart: waved 1 times"])


if __name__ == "__main__":
    unittest.main()
