"""The agent without a gateway: options, feedback rules, refusals before sending, and a stand-in gateway that stays
silent, drops the connection, closes it with an error or sends what is not the protocol."""
import socket
import struct
import threading
import unittest

from fake_gateway import FakeGateway
from harness import eventually
from kicnp_agent import ActionHandle, Agent, AgentError, AgentTimeoutError, Command, NotConnectedError, RequestRefusedError


class OptionsTest(unittest.TestCase):

    def test_badOptions_areRefusedNamingTheOption(self):
        with self.assertRaises(ValueError) as error:
            Agent("9lives", "t")
        self.assertIn("Agent name '9lives' is not a name", str(error.exception))
        with self.assertRaises(ValueError) as error:
            Agent("scout", "t", request_timeout=0)
        self.assertEqual("Option request_timeout of agent 'scout' must be above 0 seconds, not 0.", str(error.exception))
        with self.assertRaises(ValueError):
            Agent("scout", "t", kind="robotic")


class ActionHandleTest(unittest.TestCase):

    def setUp(self):
        self.sent = []
        self.handle = ActionHandle(Command("c1", "scout", "bring", {}), self.sent.append)

    def test_reports_startedOnce_thenProgress_thenOneEnd(self):
        self.handle.started()
        self.handle.started()
        self.handle.progress(0.5, "half")
        self.handle.ended("done")
        self.assertEqual([("started", "", None), ("progress", "half", 0.5), ("ended", "done", None)],
                         [(f.stage, f.detail, f.progress) for f in self.sent])
        with self.assertRaises(RuntimeError) as error:
            self.handle.failed("late")
        self.assertEqual("Command 'c1' was already reported done; no more failed reports.", str(error.exception))

    def test_progress_outsideZeroToOne_isRefusedAndNotSent(self):
        for fraction in (1.5, -0.1, float("nan"), True):
            with self.assertRaises(ValueError):
                self.handle.progress(fraction)
        self.assertEqual([], self.sent)

    def test_afterTheConnectionIsLost_reportsAreDropped(self):
        self.handle._cut()
        self.handle.started()
        self.handle.progress(0.5)
        self.handle.ended("done")
        self.assertEqual([], self.sent)
        self.assertTrue(self.handle.is_done)

    def test_afterACancelIsReported_laterReportsAreIgnored(self):
        self.assertTrue(self.handle._request_cancel("stop"))
        self.assertFalse(self.handle._request_cancel("stop again"))
        self.assertTrue(self.handle.wait_cancelled(0))
        self.handle.cancelled("stop")
        self.handle.progress(0.9, "still going")
        self.handle.ended("done anyway")
        self.assertEqual([("failed", "cancelled: stop")], [(f.stage, f.detail) for f in self.sent])


class NotConnectedTest(unittest.TestCase):

    def test_sensorBeforeConnecting_isRefused_butABadValueIsRefusedFirst(self):
        agent = Agent("scout", "t")
        with self.assertRaises(NotConnectedError) as error:
            agent.sensor("sonar", 1.5)
        self.assertEqual("Agent 'scout' is not connected; the sensor message was not sent.", str(error.exception))
        with self.assertRaises(ValueError):
            agent.sensor("sonar", float("inf"))
        with self.assertRaises(ValueError) as error:
            agent.sensor("sonar", 1.5, ttl=0.0005)
        self.assertEqual("The time to live of sensor 'sonar' must be a whole number of milliseconds from 0.001 s to a "
                         "day (86400 s), not 0.0005 s.", str(error.exception))


class EarlyCommandTest(unittest.TestCase):

    def test_aCommandSentBeforeTheAnswerToTheRegister_isCarriedOut_notPassedBy(self):
        # A gateway of this protocol answers the register first; an older one could queue a command a behavior frame
        # issued the moment the robot's presence appeared ahead of that answer.
        server = FakeGateway(before_register_answer=[
            {"type": "command", "id": "c1", "robot": "scout", "action": "wave", "args": {}}])
        self.addCleanup(server.close)
        robot = Agent("scout", "t", kind="robot", port=server.port)
        self.addCleanup(robot.close)

        @robot.action("wave")
        def wave(command, action):
            return "waved"

        robot.start_and_wait(5)
        eventually("the command is carried out", lambda: any(
            m["type"] == "feedback" and m["stage"] == "ended" for m in server.received))
        self.assertEqual([("c1", "started", ""), ("c1", "ended", "waved")],
                         [(m["id"], m["stage"], m["detail"]) for m in server.received if m["type"] == "feedback"])


class StandInGatewayTest(unittest.TestCase):

    def setUp(self):
        self.server = FakeGateway()
        self.addCleanup(self.server.close)
        self.agent = Agent("scout", "t", kind="user", port=self.server.port, request_timeout=0.3, backoff_initial=0.01,
                           backoff_max=0.05)
        self.addCleanup(self.agent.close)
        self.agent.start_and_wait(5)

    def test_aRequestWithoutAnswer_timesOutNamingTheRequest(self):
        with self.assertRaises(AgentTimeoutError) as error:
            self.agent.query("Cup")
        self.assertEqual("The server did not answer the query of class 'Cup' (request '1') within 0.3 s.",
                         str(error.exception))
        with self.assertRaises(AgentTimeoutError) as error:
            self.agent.ask("cup1", "ml", timeout=0.1)
        self.assertIn("the ask for slot 'ml' of frame 'cup1' (request '2') within 0.1 s", str(error.exception))

    def test_close_failsARequestWaitingForItsAnswer(self):
        threading.Timer(0.1, self.agent.close).start()
        with self.assertRaises(NotConnectedError) as error:
            self.agent.query("Cup", timeout=5)
        self.assertEqual("Agent 'scout' was closed.", str(error.exception))
        self.assertFalse(self.agent.is_connected)

    def test_aDroppedConnection_failsTheRequestWaitingOnIt_andTheAgentReconnects(self):
        threading.Timer(0.1, self.server.drop).start()
        with self.assertRaises(NotConnectedError) as error:
            self.agent.query("Cup", timeout=5)
        self.assertEqual("Agent 'scout' lost its connection.", str(error.exception))
        eventually("the agent is registered again", lambda: self.server.connections == 2 and self.agent.is_connected)

    def test_aServerThatClosesWithAnError_isNamedInTheFailureOfTheRequestWaiting(self):
        def close_with_error(server, message):
            server.send({"type": "error", "code": "heartbeat_timeout", "message": "Nothing was heard."})
            server.drop()
        self.server._answer = close_with_error
        with self.assertLogs("kicnp_agent", "WARNING"), self.assertRaises(NotConnectedError) as error:
            self.agent.query("Cup", timeout=5)
        self.assertEqual("Agent 'scout' lost its connection: the server closed it (heartbeat_timeout): Nothing was "
                         "heard.", str(error.exception))

    def test_aFrameTooLargeForTheServer_isTheAnswerToTheRequestInFlight(self):
        def too_large(server, message):
            server.send({"type": "error", "code": "frame_too_large", "message": "The frame is 2 MiB, above 1 MiB."})
            server.drop()
        self.server._answer = too_large
        with self.assertLogs("kicnp_agent", "WARNING"), self.assertRaises(RequestRefusedError) as error:
            self.agent.assert_frames("<FRAME/>", timeout=5)
        self.assertEqual(("frame_too_large", "The frame is 2 MiB, above 1 MiB."), (error.exception.code,
                                                                                 str(error.exception)))

    def test_aRequestRefusedForItsLength_whileStillBeingWritten_failsWithTheServersReason(self):
        # The server refuses as soon as it reads the length, and closes after saying so, while the agent may still be
        # writing: here it reads nothing more, so the write is stuck when the agent reads the refusal and the end of
        # the stream and closes its socket. The caller hears the server's reason, not that the write failed.
        server = FakeGateway(refuse_longer_than=1 << 20)
        self.addCleanup(server.close)
        agent = Agent("scout", "t", kind="user", port=server.port, max_frame_bytes=64 << 20, backoff_initial=0.01,
                      backoff_max=0.05)
        self.addCleanup(agent.close)
        agent.start_and_wait(5)
        with self.assertLogs("kicnp_agent", "WARNING"), self.assertRaises(RequestRefusedError) as error:
            agent.relay_to("bob", "note", "x" * (32 << 20), timeout=10)  # more than loopback's buffers hold
        self.assertEqual("frame_too_large", error.exception.code)
        self.assertIn("longer than this server accepts (1048576 bytes at most)", str(error.exception))

    def test_whatIsNotTheProtocol_dropsTheConnection_andTheAgentReconnects(self):
        with self.assertLogs("kicnp_agent", "INFO") as logged:
            self.server.send({"type": "ack", "id": "x"}, version=2)
            eventually("the agent is registered again", lambda: self.server.connections == 2 and self.agent.is_connected)
            self.server.send_bytes(b"not json")
            eventually("the agent is registered a third time", lambda: self.server.connections == 3
                       and self.agent.is_connected)
        lost = [r.getMessage() for r in logged.records if "lost its connection" in r.getMessage()]
        self.assertEqual(2, len(lost), lost)
        self.assertIn("(The server speaks protocol version 2, not 1.); reconnecting.", lost[0])
        self.assertIn("(The server sent a frame that is not UTF-8 JSON", lost[1])


    def test_aLengthOverMaxFrameBytes_dropsTheConnectionAtOnce_notWaitingForThePayload(self):
        with self.assertLogs("kicnp_agent", "INFO") as logged:
            self.server.send_raw(struct.pack(">I", 1024 * 1024 + 1) + b'{"v":1,')  # and the rest never comes
            # Well within server_silence (40 s): the agent did not wait for the 1 MiB to come.
            eventually("the agent is registered again", lambda: self.server.connections == 2 and self.agent.is_connected,
                       timeout=5)
        self.assertIn("(The server sent a frame of 1048577 bytes, more than the 1048576 bytes this agent accepts "
                      "(max_frame_bytes).); reconnecting.", "\n".join(logged.output))


class UnreachableServerTest(unittest.TestCase):

    def test_waitConnected_namesTheLastFailure(self):
        bound = socket.socket()  # a port bound but not listening: every connection is refused
        self.addCleanup(bound.close)
        bound.bind(("127.0.0.1", 0))
        port = bound.getsockname()[1]
        agent = Agent("scout", "t", port=port, backoff_initial=0.01, backoff_max=0.05)
        self.addCleanup(agent.close)
        with self.assertRaises(AgentTimeoutError) as error:
            agent.start_and_wait(0.5)
        self.assertRegex(str(error.exception), r"^Agent 'scout' was not registered with 127\.0\.0\.1:%d within 0\.5 s; "
                                               r"the last attempt failed: .*[Rr]efused.*\.$" % port)

    def test_aServerSilentLongerThanServerSilence_isTakenForLost(self):
        server = FakeGateway()
        self.addCleanup(server.close)
        agent = Agent("scout", "t", port=server.port, server_silence=0.3, heartbeat_interval=0.1, backoff_initial=0.01,
                      backoff_max=0.05)
        self.addCleanup(agent.close)
        with self.assertLogs("kicnp_agent", "INFO") as logged:
            agent.start_and_wait(5)
            eventually("the agent connects again", lambda: server.connections == 2 and agent.is_connected)
        self.assertIn("(The server sent nothing for 0.3 s.); reconnecting.", "\n".join(logged.output))


class BrokenCapabilitiesTest(unittest.TestCase):

    def test_aProgramErrorWhileConnecting_stopsTheAgentNamingIt(self):
        class Broken(Agent):
            def capabilities(self):
                raise RuntimeError("no frames today")

        server = FakeGateway()
        self.addCleanup(server.close)
        agent = Broken("scout", "t", port=server.port)
        self.addCleanup(agent.close)
        with self.assertLogs("kicnp_agent", "ERROR") as logged, self.assertRaises(AgentError) as error:
            agent.start_and_wait(5)
        self.assertEqual("Agent 'scout' failed: RuntimeError: no frames today.", str(error.exception))
        self.assertEqual(["Agent 'scout' failed: RuntimeError: no frames today. The agent stops."],
                         [r.getMessage() for r in logged.records])
        self.assertIs(error.exception, agent.stopped)


if __name__ == "__main__":
    unittest.main()
