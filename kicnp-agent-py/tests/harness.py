"""The gateway side of the tests: PythonSdkTest (kicnp-gateway) starts a real gateway, runs this suite with its port
and agents in the environment, and answers requests written to stdout on stdin. Without it (KICNP_PORT unset), the
tests that need a gateway are skipped and the others run alone.
"""
import json
import os
import sys
import threading
import time
import unittest

from kicnp_agent import Agent


class Harness:
    """The Java test that runs the gateway: asks it to act (send a command, restart) or to tell what it saw."""

    def __init__(self, environ):
        self.port = int(environ["KICNP_PORT"])
        self.agents = {}
        for entry in environ["KICNP_AGENTS"].split(","):
            name, kind, token = entry.split(":")
            self.agents[name] = (kind, token)
        self._lock = threading.Lock()

    def call(self, op, **args):
        with self._lock:
            sys.stdout.write("KICNP-HARNESS " + json.dumps(dict(args, op=op)) + "\n")
            sys.stdout.flush()
            reply = json.loads(sys.stdin.readline())
        if not reply["ok"]:
            raise AssertionError("The gateway's side refused '%s': %s" % (op, reply["error"]))
        return reply

    def heard(self, command_id):
        """What the platform's feedback listener heard of one command, in order."""
        return [h for h in self.call("heard")["heard"] if h.split(":")[0].split(" ")[1] == command_id]

    def agent(self, name, agent_class=Agent, **options):
        """An agent of the gateway's agent file, with fast heartbeats (the gateway drops agents silent for 3 s)
        and fast reconnects, so that the suite runs quickly."""
        kind, token = self.agents[name]
        token = options.pop("token", token)
        settings = dict(kind=kind, port=self.port, heartbeat_interval=0.5, backoff_initial=0.05, backoff_max=0.5)
        settings.update(options)
        return agent_class(name, token, **settings)


HARNESS = Harness(os.environ) if "KICNP_PORT" in os.environ else None


class GatewayTestCase(unittest.TestCase):
    """A test against the gateway: its agents are closed after it, whatever happens."""

    def setUp(self):
        if HARNESS is None:
            self.skipTest("needs the gateway of PythonSdkTest (KICNP_PORT is not set)")
        self.gateway = HARNESS

    def connect(self, name, agent_class=Agent, **options):
        agent = self.gateway.agent(name, agent_class, **options)
        self.addCleanup(agent.close)
        return agent


def eventually(what, condition, timeout=10.0):
    """Polls ``condition`` until it is true; fails naming ``what`` after ``timeout`` seconds."""
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError("Timed out after %g s waiting until %s." % (timeout, what))
        time.sleep(0.02)
