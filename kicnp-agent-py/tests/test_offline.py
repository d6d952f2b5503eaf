"""The agent without a gateway: options, feedback rules, refusals before sending, and a server that never answers
(a socket of the test's own that speaks only the handshake)."""
import json
import socket
import struct
import threading
import unittest

from kicnp_agent import (ActionHandle, Agent, AgentTimeoutError, Command, NotConnectedError)


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


class SilentServer:
    """Accepts one agent, authenticates and registers it, then reads everything and answers nothing."""

    def __init__(self):
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.received = []
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self):
        conn, _ = self.listener.accept()
        with conn:
            try:
                while True:
                    message = self._read(conn)
                    self.received.append(message["type"])
                    if message["type"] == "hello":
                        self._write(conn, {"type": "auth_result", "id": message["id"], "accepted": True, "server": "t"})
                    elif message["type"] == "register":
                        self._write(conn, {"type": "ack", "id": message["id"]})
            except (OSError, struct.error, ValueError):
                return

    @staticmethod
    def _read(conn):
        header = conn.recv(4, socket.MSG_WAITALL)
        return json.loads(conn.recv(struct.unpack(">I", header)[0], socket.MSG_WAITALL))

    @staticmethod
    def _write(conn, message):
        payload = json.dumps(dict(message, v=1)).encode()
        conn.sendall(struct.pack(">I", len(payload)) + payload)

    def close(self):
        self.listener.close()


class RequestTimeoutTest(unittest.TestCase):

    def setUp(self):
        self.server = SilentServer()
        self.addCleanup(self.server.close)
        self.agent = Agent("scout", "t", kind="user", port=self.server.port, request_timeout=0.3)
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


if __name__ == "__main__":
    unittest.main()
