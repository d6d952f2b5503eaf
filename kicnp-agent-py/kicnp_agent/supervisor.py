"""The connection's life, for an :class:`~kicnp_agent.agent.Agent`: the Python counterpart of the Java SDK's
Supervisor (module kicnp-agent-base).

:class:`Supervisor` connects, says hello and registers, renews the agent's subscriptions, sends heartbeats, reads what
the server sends and routes it (answers to the pending requests, commands and cancels to the command runner, feedback
to the tickets, relays and changes to the event queue), and after a lost connection or a server restart connects
again with exponential backoff and equal jitter, until the agent is closed or stops for good. It is kept apart from
:class:`~kicnp_agent.agent.Agent`, the API a program sees, because the connection's state (the connection, whether
registered, why it stopped) changes only here; the agent only asks it to send and to report.
"""
import functools
import logging
import random
import threading
import time

from .connection import Connection
from .errors import AgentError, AuthenticationError, NotConnectedError, ProtocolError, RequestRefusedError
from .messages import Changed, Command, Feedback, Relay, value_from_json

LOG = logging.getLogger("kicnp_agent")
# Errors after which the server closes the connection (docs/protocol.md, "Error codes").
_CLOSING = {"frame_too_large", "bad_json", "unsupported_version", "unknown_type", "bad_message", "not_authenticated",
            "heartbeat_timeout", "overloaded", "superseded", "internal"}


class Supervisor:
    """Keeps one agent connected, on the agent's supervising thread (:meth:`run`)."""

    def __init__(self, agent, pending, events, runner, closed, ids):
        """``pending``, ``events``, ``runner``, ``closed`` and ``ids`` are the agent's: its :class:`PendingRequests`,
        :class:`EventQueue`, :class:`CommandRunner`, closed event and id counter."""
        self._agent = agent
        self._pending = pending
        self._events = events
        self._runner = runner
        self._closed = closed
        self._ids = ids
        self.connection = None
        """The registered connection, or None."""
        self.registered = threading.Event()
        self.fatal = None
        """Why the agent stopped for good, or None."""
        self.last_failure = None
        """Why the last connection attempt (or connection) failed, for a timeout's message."""
        self._closing_error = None
        self._early = []  # messages read before the register's answer, for the read loop

    @property
    def _options(self):
        return self._agent.options

    @property
    def _name(self):
        return self._agent.name

    def run(self):
        """Connects, and connects again after each loss, until the agent is closed or stops for good."""
        delay = self._options.backoff_initial
        while not self._closed.is_set():
            connection = None
            fatal = None
            try:
                connection = Connection.open(self._options)
                if self._closed.is_set():  # closed while connecting
                    return
                self._handshake(connection)
                delay = self._options.backoff_initial
                self._read_loop(connection)
            except AuthenticationError as e:
                fatal = (e, None)
                return
            except (OSError, ProtocolError) as e:
                if self._closed.is_set():
                    return
                self.last_failure = str(e) or type(e).__name__
                LOG.info("Agent '%s' lost its connection to %s:%d (%s); reconnecting.", self._name, self._options.host,
                         self._options.port, self.last_failure)
            except Exception as e:  # a bug in the program (say, in capabilities()) or a server we do not understand
                fatal = (AgentError("Agent '%s' failed: %s"
                                    % (self._name, _sentence("%s: %s" % (type(e).__name__, e)))), e)
                return
            finally:
                if connection is not None:
                    connection.close()
                self._lost()
                if fatal is not None:  # only now: whoever sees `stopped` set sees the agent disconnected too
                    self._stop(*fatal)
            if self._closed.wait(delay / 2 + random.uniform(0, delay / 2)):  # "equal jitter"
                return
            delay = min(delay * 2, self._options.backoff_max)

    def _stop(self, error, cause=None):
        self.fatal = error
        LOG.error("%s The agent stops.", error, exc_info=cause)

    def _handshake(self, connection):
        self._early = []  # what an earlier connection left
        connection.send({"type": "hello", "id": "hello", "agent": self._name, "kind": self._agent.kind.value,
                         "token": self._options.token})
        auth = self._await_direct(connection, "hello")
        if auth["type"] == "error" or not auth["accepted"]:
            reason = auth.get("message") or auth.get("reason") or "no reason given"
            raise AuthenticationError("The server refused agent '%s' (kind %s): %s"
                                      % (self._name, self._agent.kind.value, _sentence(reason)))
        connection.send({"type": "register", "id": "register", "capabilities": self._agent.capabilities()})
        registered = self._await_direct(connection, "register")
        if registered["type"] == "error":
            raise AuthenticationError("The server refused to register agent '%s' (%s): %s"
                                      % (self._name, registered["code"], _sentence(registered["message"])))
        self.connection = connection
        for of_class in self._agent._subscribed():
            connection.send({"type": "subscribe", "id": "resubscribe-%d" % next(self._ids), "ofClass": of_class})
        self.registered.set()
        self._start_heartbeats(connection)
        LOG.info("Agent '%s' registered with %s:%d.", self._name, self._options.host, self._options.port)
        self._events.put(self._agent.on_connected)

    def _await_direct(self, connection, request_id):
        while True:
            message = connection.read()
            if message["type"] in ("auth_result", "ack") and message["id"] == request_id:
                return message
            if message["type"] == "error" and message.get("id", request_id) in (request_id, ""):
                return message
            if message["type"] != "heartbeat":  # heartbeats may come before registration; anything else waits
                self._early.append(message)     # for the read loop (a server of this protocol sends none then)

    def _start_heartbeats(self, connection):
        interval = self._options.heartbeat_interval

        def beat():
            while connection.is_open and not self._closed.is_set():
                quiet = time.monotonic() - connection.last_sent
                if self._closed.wait(max(0.0, interval - quiet)):
                    return
                if connection.is_open and time.monotonic() - connection.last_sent >= interval:
                    try:
                        connection.send({"type": "heartbeat", "time": int(time.time() * 1000)})
                    except OSError:
                        return  # the connection is gone; the read loop notices and reconnects

        threading.Thread(target=beat, name="agent-heartbeat-" + self._name, daemon=True).start()

    def _read_loop(self, connection):
        # What came before the answer to the register: an older gateway could queue a command ahead of it.
        early, self._early = self._early, []
        for m in early:
            self._handle(m)
        while not self._closed.is_set():
            self._handle(connection.read())

    def _handle(self, m):
        kind = m["type"]
        if kind == "command":
            self._runner.command(Command(m["id"], m["robot"], m["action"], dict(m["args"])))
        elif kind == "cancel":
            self._runner.cancel(m["command"], m["reason"])
        elif kind == "feedback":
            self._agent._feedback(Feedback(m["id"], m["robot"], m["stage"], m["detail"], m.get("progress")))
        elif kind == "relay":
            relay = Relay(m["id"], m["from"], m["subject"], m["body"], m.get("toAgent"), m.get("toKind"))
            self._events.put(functools.partial(self._agent.on_relay, relay))
        elif kind == "changed":
            values = m.get("values")
            change = Changed(m["ofClass"], m["change"], m["name"], m.get("frame"),
                             None if values is None else value_from_json(values))
            self._events.put(functools.partial(self._agent._changed, change))
        elif kind == "error":
            self._error(m)
        elif kind != "heartbeat":
            self._complete(m)

    def _error(self, m):
        if m["code"] == "superseded":
            raise AuthenticationError("Agent '%s' was replaced by a newer connection under its name: %s"
                                      % (self._name, _sentence(m["message"])))
        if m.get("id"):
            self._complete(m)
            return
        LOG.warning("Agent '%s': the server says %s: %s", self._name, m["code"], m["message"])
        if m["code"] in _CLOSING:
            self._closing_error = m

    def _complete(self, answer):
        if not self._pending.answer(answer) and answer["type"] == "error":
            LOG.warning("Agent '%s': request '%s' was refused (%s): %s", self._name, answer["id"], answer["code"],
                        answer["message"])

    def _lost(self):
        was = self.registered.is_set()
        self.registered.clear()
        self.connection = None
        why, self._closing_error = self._closing_error, None
        if self._closed.is_set():
            self._pending.fail_all(NotConnectedError("Agent '%s' was closed." % self._name))
        elif why is not None and why["code"] == "frame_too_large":
            # The request in flight was too long for the server, which said so and closed: that is its answer.
            self._pending.fail_all(RequestRefusedError(why["code"], why["message"]))
        else:
            self._pending.fail_all(NotConnectedError(
                "Agent '%s' lost its connection%s" % (self._name, "." if why is None
                                                      else ": the server closed it (%s): %s"
                                                      % (why["code"], _sentence(why["message"])))))
        self._agent._commands_lost()
        self._runner.connection_lost("agent '%s' was closed" % self._name if self._closed.is_set()
                                     else "the connection to the gateway was lost")
        if was and not self._closed.is_set():
            self._events.put(lambda: self._agent.on_disconnected("connection lost"))


def _sentence(text):
    """Text as the end of a sentence: with a full stop, unless it has one."""
    text = text.strip()
    return text if text.endswith((".", "!", "?")) else text + "."
