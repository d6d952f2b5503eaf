"""Commands against a real gateway: from the platform (the gateway's ActionSink) and from a user agent, with their
feedback, failures and cancels."""
import threading
import unittest

from harness import GatewayTestCase, eventually
from kicnp_agent import ActionFailedError, Agent, RequestRefusedError


class RobotCommandsTest(GatewayTestCase):

    def robot(self):
        robot = self.connect("pyrobot")
        seen = {}

        @robot.action("wave")
        def wave(command, handle):
            seen["thread"] = threading.current_thread().name
            handle.progress(0.5, "halfway")
            return "waved %s times" % command.args["times"]

        @robot.action("grab")
        def grab(command, handle):
            raise ValueError("no arm")

        @robot.action("patrol")
        def patrol(command, handle):
            seen["patrolling"] = True
            while not handle.wait_cancelled(0.02):
                pass
            seen["cancel_reason"] = handle.cancel_reason
            return "patrolled"  # reported cancelled already: ignored

        robot.start_and_wait(10)
        return robot, seen

    def test_command_fromThePlatform_runsItsHandlerOffTheReaderThread_andTheFeedbackReachesThePlatform(self):
        robot, seen = self.robot()
        self.gateway.call("command", id="py-wave", robot="pyrobot", action="wave", args={"times": "3"})
        eventually("the platform hears the end of py-wave", lambda: len(self.gateway.heard("py-wave")) == 3)
        self.assertEqual(["started py-wave", "progress py-wave 0.5 halfway", "ended py-wave: waved 3 times"],
                         self.gateway.heard("py-wave"))
        self.assertEqual("command-py-wave", seen["thread"])
        # The gateway keeps the latest feedback as a frame, for slot conditions.
        self.assertEqual("ended", self.gateway.call("value", frame="feedback_pyrobot_wave", slot="status")["value"])
        self.assertEqual(0, robot.commands_in_flight)

    def test_handlerThatRaises_failsTheCommandWithTheExceptionsMessage(self):
        self.robot()
        with self.assertLogs("kicnp_agent", "WARNING") as logged:
            self.gateway.call("command", id="py-raise", robot="pyrobot", action="grab", args={})
            eventually("py-raise ends", lambda: len(self.gateway.heard("py-raise")) == 2)
        self.assertIn("Agent 'pyrobot' failed on command 'py-raise'.", [r.getMessage() for r in logged.records])
        self.assertEqual(["started py-raise", "failed py-raise: Agent 'pyrobot' failed on 'grab': ValueError: no arm"],
                         self.gateway.heard("py-raise"))

    def test_actionWithoutHandler_failsNamingTheActionsItHandles(self):
        self.robot()
        self.gateway.call("command", id="py-dance", robot="pyrobot", action="dance", args={})
        eventually("py-dance ends", lambda: self.gateway.heard("py-dance"))
        self.assertEqual(["failed py-dance: Agent 'pyrobot' has no handler for action 'dance' "
                          "(it handles: grab, patrol, wave)."], self.gateway.heard("py-dance"))

    def test_cancelFromThePlatform_reachesTheRunningHandler_andEndsTheCommandAsCancelled(self):
        robot, seen = self.robot()
        self.gateway.call("command", id="py-cancel", robot="pyrobot", action="patrol", args={})
        eventually("the patrol runs", lambda: seen.get("patrolling"))
        self.assertTrue(self.gateway.call("cancel", robot="pyrobot", command="py-cancel", reason="stop now")["cancelled"])
        eventually("py-cancel ends", lambda: len(self.gateway.heard("py-cancel")) == 2)
        self.assertEqual(["started py-cancel", "failed py-cancel: cancelled: stop now"], self.gateway.heard("py-cancel"))
        eventually("the handler sees the cancel", lambda: "cancel_reason" in seen)
        self.assertEqual("stop now", seen["cancel_reason"])
        self.assertEqual(0, robot.commands_in_flight)

    def test_closingTheRobot_cancelsItsCommandInFlight_andThePlatformHearsItFailed(self):
        robot, seen = self.robot()
        self.gateway.call("command", id="py-close", robot="pyrobot", action="patrol", args={})
        eventually("the patrol runs", lambda: seen.get("patrolling"))
        robot.close()
        eventually("the handler sees the cancel", lambda: "cancel_reason" in seen)
        self.assertEqual("agent 'pyrobot' was closed", seen["cancel_reason"])
        eventually("py-close fails", lambda: len(self.gateway.heard("py-close")) == 2)
        self.assertEqual("failed py-close: agent 'pyrobot' disconnected", self.gateway.heard("py-close")[1])


class Braking(Agent):
    """A robot whose brakes fail when it is asked to stop."""

    def on_cancel(self, handle, reason):
        raise RuntimeError("brakes")


class CancelHandlerTest(GatewayTestCase):

    def test_anOnCancelThatRaises_endsTheCommandAsCancelFailed_notCancelled(self):
        robot = self.connect("pyrobot", Braking)
        running = threading.Event()

        @robot.action("patrol")
        def patrol(command, handle):
            running.set()
            handle.wait_cancelled(10)

        robot.start_and_wait(10)
        self.gateway.call("command", id="py-brakes", robot="pyrobot", action="patrol", args={})
        self.assertTrue(running.wait(10))
        with self.assertLogs("kicnp_agent", "WARNING") as logged:
            self.gateway.call("cancel", robot="pyrobot", command="py-brakes", reason="stop now")
            eventually("py-brakes ends", lambda: len(self.gateway.heard("py-brakes")) == 2)
        self.assertEqual("failed py-brakes: cancel failed: RuntimeError: brakes (agent 'pyrobot', asked to stop: stop "
                         "now); the robot may not have stopped", self.gateway.heard("py-brakes")[1])
        self.assertIn("Agent 'pyrobot' failed to cancel 'py-brakes'.", [r.getMessage() for r in logged.records])
        self.assertTrue(robot.is_connected)


class UserCommandsTest(GatewayTestCase):

    def test_userAgentsCommand_endsWithTheRobotsResult_andCanBeCancelled(self):
        robot = self.connect("pyrobot")
        started = threading.Event()

        @robot.action("wave")
        def wave(command, handle):
            handle.progress(1.0, "done")
            return "waved %s times" % command.args["times"]

        @robot.action("patrol")
        def patrol(command, handle):
            started.set()
            handle.wait_cancelled(10)

        robot.start_and_wait(10)
        user = self.connect("pyuser").start_and_wait(10)

        ticket = user.command("pyrobot", "wave", {"times": 2})
        self.assertEqual("waved 2 times", ticket.result(10))
        self.assertEqual(["started", "progress", "ended"], [f.stage for f in ticket.feedback])
        self.assertEqual(1.0, ticket.feedback[1].progress)

        patrol_ticket = user.command("pyrobot", "patrol")
        self.assertTrue(started.wait(10))
        user.cancel("pyrobot", patrol_ticket.command.id, "enough")
        with self.assertRaises(ActionFailedError) as failed:
            patrol_ticket.result(10)
        self.assertEqual("Command '%s' (patrol) to robot 'pyrobot' failed: cancelled: enough (asked by 'pyuser')"
                         % patrol_ticket.command.id, str(failed.exception))

    def test_commandToARobotNotConnected_isRefusedNamingIt(self):
        user = self.connect("pyuser").start_and_wait(10)
        with self.assertRaises(RequestRefusedError) as refused:
            user.command("pyrobot2", "wave")
        self.assertEqual("unknown_agent", refused.exception.code)
        self.assertRegex(str(refused.exception), r"^The server refused command 'pyuser-\w+-\d+' \(wave\) to robot "
                                                 r"'pyrobot2' \(unknown_agent\): .+")


if __name__ == "__main__":
    unittest.main()
