"""README.md's robot is examples/tea_robot.py verbatim, and that file runs: against the gateway of PythonSdkTest it
registers, carries out a command from the platform, reports its sonar, and stops cleanly on Ctrl-C."""
import os
import pathlib
import re
import signal
import subprocess
import sys
import unittest

from harness import GatewayTestCase, eventually

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "examples" / "tea_robot.py"


class ReadmeTest(unittest.TestCase):

    def test_readmesFirstExample_isTheTeaRobotFile(self):
        readme = (ROOT / "README.md").read_text(encoding="utf-8")
        first = re.search(r"```python\n(.*?)```", readme, re.S)
        self.assertIsNotNone(first, "README.md has no python example")
        self.assertEqual(EXAMPLE.read_text(encoding="utf-8"), first.group(1))


class TeaRobotTest(GatewayTestCase):

    def test_teaRobot_bringsTea_whenThePlatformAsks_andStopsOnCtrlC(self):
        kind, token = self.gateway.agents["scout"]
        env = dict(os.environ, KICNP_TOKEN=token, KICNP_PORT=str(self.gateway.port), PYTHONPATH=str(ROOT))
        if os.environ.get("KICNP_SDK_INSTALLED"):
            # Run by a Python that has the SDK pip-installed (PythonSdkTest): the robot imports it from there.
            del env["PYTHONPATH"]
            where = subprocess.run([sys.executable, "-c", "import kicnp_agent; print(kicnp_agent.__file__)"],
                                   env=env, cwd=str(EXAMPLE.parent), capture_output=True, text=True, check=True)
            self.assertIn("site-packages", where.stdout)
            self.assertNotIn(str(ROOT / "kicnp_agent"), where.stdout)
        robot = subprocess.Popen([sys.executable, str(EXAMPLE)], env=env, stdin=subprocess.DEVNULL,
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        self.addCleanup(robot.kill)
        eventually("scout is registered", lambda: "scout" in self.gateway.call("agents")["agents"]
                   or robot.poll() is not None)
        self.assertIsNone(robot.poll(), "the tea robot exited early")
        self.gateway.call("command", id="py-tea", robot="scout", action="bring", args={"item": "milk"})
        eventually("the tea comes", lambda: self.gateway.heard("py-tea")[-1:] == ["ended py-tea: brought a cup of milk"])
        self.assertEqual(["started py-tea", "progress py-tea 0.3333333333333333 leg 1 of 3",
                          "progress py-tea 0.6666666666666666 leg 2 of 3", "progress py-tea 1.0 leg 3 of 3",
                          "ended py-tea: brought a cup of milk"], self.gateway.heard("py-tea"))
        self.assertEqual([0.5], self.gateway.call("value", frame="signal_scout_sonar", slot="values")["value"])

        robot.send_signal(signal.SIGINT)
        output, _ = robot.communicate(timeout=10)
        self.assertEqual(0, robot.returncode, output.decode("utf-8", "replace"))
        eventually("scout is gone", lambda: "scout" not in self.gateway.call("agents")["agents"])


if __name__ == "__main__":
    unittest.main()
