"""TLS against a real gateway (PythonSdkTest's TLS run): the agent trusts exactly the server's certificate."""
import os
import unittest

from harness import GatewayTestCase, eventually
from kicnp_agent import AgentTimeoutError

TRUST = os.environ.get("KICNP_TLS_TRUST")
OTHER = os.environ.get("KICNP_TLS_OTHER")


@unittest.skipUnless(TRUST and OTHER, "needs PythonSdkTest's TLS gateway (KICNP_TLS_TRUST, KICNP_TLS_OTHER)")
class TlsTest(GatewayTestCase):

    def test_agentTrustingTheServersCertificate_takesACommandAndQueries(self):
        robot = self.connect("pyrobot", tls_trust=TRUST)

        @robot.action("wave")
        def wave(command, handle):
            return "waved %s times" % command.args["times"]

        robot.start_and_wait(15)
        self.assertEqual(["cup1"], [f.name for f in robot.query("Cup")])
        self.gateway.call("command", id="py-tls", robot="pyrobot", action="wave", args={"times": "1"})
        eventually("the command ends", lambda: self.gateway.heard("py-tls")
                   == ["started py-tls", "ended py-tls: waved 1 times"])

    def test_agentTrustingAnotherCertificate_isNotRegistered_andSaysWhy(self):
        agent = self.connect("pyrobot", tls_trust=OTHER)
        with self.assertRaises(AgentTimeoutError) as timeout:
            agent.start_and_wait(2)
        self.assertIn("was not registered with 127.0.0.1:%d within 2 s; the last attempt failed: " % self.gateway.port,
                      str(timeout.exception))
        self.assertIn("CERTIFICATE_VERIFY_FAILED", str(timeout.exception))


if __name__ == "__main__":
    unittest.main()
