"""The agent: the Python counterpart of org.kicnp.agent.AgentBase, the paper's "Agent Base Classes"."""
import functools
import itertools
import logging
import random
import threading
import time

from .actions import CommandRunner, CommandTicket
from .connection import Connection
from .dispatch import EventQueue, PendingRequests
from .errors import (AgentError, AgentTimeoutError, AuthenticationError, NotConnectedError, ProtocolError,
                     RequestRefusedError)
from .frames import Frame
from .messages import (Changed, Command, Feedback, NotFired, ProofNode, Reason, Relay, value_from_json,
                       value_to_json)
from .options import AgentKind, AgentOptions
from .wire import MAX_NAME_LENGTH, check_lengths, length

LOG = logging.getLogger("kicnp_agent")
_MAX_TTL_MS = 86400000
# Errors after which the server closes the connection (docs/protocol.md, "Error codes").
_CLOSING = {"frame_too_large", "bad_json", "unsupported_version", "unknown_type", "bad_message", "not_authenticated",
            "heartbeat_timeout", "overloaded", "superseded", "internal"}


class Agent:
    """A K-ICNP agent: connects, authenticates, registers its capabilities, keeps heartbeats, and after a lost
    connection or a server restart reconnects with exponential backoff and jitter, registers again and renews its
    subscriptions.

    A robot registers a handler per action with :meth:`action`; a handler runs on a thread of its own, the SDK
    reports ``started`` before it, its return value as ``ended`` and an exception as ``failed``. Requests
    (:meth:`query`, :meth:`ask`, ...) block the calling thread and raise an :class:`AgentError` subclass. Relays and
    change notifications are delivered in order on one event thread, to :meth:`on_relay`, :meth:`on_changed` or a
    subscription's callback: override them in a subclass, or assign a function to the instance's attribute.
    """

    def __init__(self, name, token, *, capabilities=(), **options):
        """``options`` are those of :class:`AgentOptions` (``kind``, ``host``, ``port``, ``tls_trust``, ...);
        ``capabilities`` are frames (XML text, see :func:`frame_xml`) registered each time the agent connects."""
        self.options = AgentOptions(name=name, token=token, **options)
        self._capabilities = list(capabilities)
        self._actions = {}
        self._callbacks = {}
        self._subscriptions = []
        self._pending = PendingRequests()
        self._tickets = {}
        self._lock = threading.Lock()
        self._ids = itertools.count(1)
        # Part of this agent object's command ids, so two runs of one agent never share an id at a robot.
        self._command_ids = _base36(int(time.time() * 1000))
        self._runner = CommandRunner(name, self._run_command, lambda handle, reason: self.on_cancel(handle, reason),
                                     self._send_feedback)
        self._closed = threading.Event()
        self._events = EventQueue(name, self._closed)
        self._connection = None
        self._registered = threading.Event()
        self._fatal = None
        self._closing_error = None
        self._last_failure = None
        self._threads = []

    # ---- what a program registers or overrides ----

    def capabilities(self):
        """The frames (XML) describing what this agent can do, registered (all or none) each time it connects."""
        return list(self._capabilities)

    def action(self, name):
        """A decorator: ``@robot.action("bring")`` makes the function the handler of that action.

        The handler is called as ``handler(command, handle)`` on a thread of its own after ``started`` was reported;
        it reports progress through ``handle``, returns the result (text, reported as ``ended``) or raises (reported
        as ``failed`` with the exception's message). It may also end the command through the handle itself. Once a
        cancel was asked for (``handle.cancel_requested``), what it returns or raises is not reported: :meth:`on_cancel`
        reports the end.
        """
        def register(handler):
            self._actions[name] = handler
            return handler
        return register

    def on_command(self, command, handle):
        """A command for an action without a handler; reports through ``handle``. By default it fails, saying so."""
        handle.failed("Agent '%s' has no handler for action '%s' (it handles: %s)."
                      % (self.name, command.action, ", ".join(sorted(self._actions)) or "none"))

    def on_cancel(self, handle, reason):
        """A request to stop ``handle.command``. By default it is reported cancelled at once (the handler sees
        ``handle.cancel_requested`` and its later reports are ignored); a robot that can stop overrides this, stops,
        then reports. If it raises before the command was reported done, the command fails with "cancel failed: "."""
        handle.cancelled(reason)

    def on_relay(self, relay):
        """A message (a :class:`Relay`) relayed from another agent."""

    def on_changed(self, change):
        """A change (a :class:`Changed`) to a frame of a class subscribed to without a callback."""

    def on_connected(self):
        """Called on the event thread each time the agent is registered, first and after every reconnect."""

    def on_disconnected(self, reason):
        """Called on the event thread when a registered connection is lost; the agent is reconnecting."""

    # ---- life cycle ----

    @property
    def name(self):
        return self.options.name

    @property
    def kind(self):
        return self.options.kind

    @property
    def is_connected(self):
        """Whether the agent is registered right now."""
        return self._registered.is_set()

    @property
    def commands_in_flight(self):
        """How many commands this robot took and has neither reported done nor lost with its connection."""
        return self._runner.in_flight

    @property
    def stopped(self):
        """Why the agent stopped for good (refused, or replaced by a newer connection), or None while it runs."""
        return self._fatal

    def start(self):
        """Starts connecting in the background and returns at once; see :meth:`wait_connected`."""
        if self._threads:
            raise RuntimeError("Agent '%s' was already started." % self.name)
        for name, target in (("agent-" + self.name, self._supervise), ("agent-events-" + self.name, self._events.run)):
            thread = threading.Thread(target=target, name=name, daemon=True)
            self._threads.append(thread)
            thread.start()
        return self

    def wait_connected(self, timeout):
        """Waits until the agent is registered; raises :class:`AuthenticationError` when the server refused it,
        :class:`AgentTimeoutError` (naming the last failure) when it is not registered within ``timeout`` seconds."""
        deadline = time.monotonic() + timeout
        while not self._registered.is_set() and self._fatal is None and not self._closed.is_set():
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                break
            self._registered.wait(min(0.05, remaining))
        if self._fatal is not None:
            raise self._fatal
        if not self._registered.is_set():
            last = self._last_failure
            raise AgentTimeoutError("Agent '%s' was not registered with %s:%d within %g s%s"
                                    % (self.name, self.options.host, self.options.port, timeout,
                                       "." if last is None else "; the last attempt failed: " + _sentence(last)))

    def start_and_wait(self, timeout=10.0):
        """Starts the agent and waits until it is registered (see :meth:`wait_connected`)."""
        self.start()
        self.wait_connected(timeout)
        return self

    def run_forever(self):
        """Starts the agent (unless started) and serves until :meth:`close` or Ctrl-C; raises why it stopped for good."""
        if not self._threads:
            self.start()
        try:
            while not self._closed.wait(0.5):
                if self._fatal is not None:
                    raise self._fatal
        except KeyboardInterrupt:
            LOG.info("Agent '%s' interrupted; closing.", self.name)
        finally:
            self.close()

    def close(self):
        """Disconnects for good: commands in flight are cancelled and requests waiting fail with NotConnectedError."""
        self._closed.set()
        connection = self._connection
        if connection is not None:
            connection.close()
        current = threading.current_thread()
        for thread in self._threads:
            if thread is not current:
                thread.join(2.0)
        self._pending.fail_all(NotConnectedError("Agent '%s' was closed." % self.name))

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # ---- what an agent can do ----

    def sensor(self, sensor, *values, ttl=None):
        """Reports a sensor signal; the server keeps the latest as ``signal_AGENT_SENSOR`` (a SensorSignal).

        With ``ttl`` (seconds, whole milliseconds from 0.001 to a day) the reading holds only that long unless a newer
        one of the same sensor comes: for readings a robot repeats while they hold. Raises ValueError for a NaN or
        infinite value or a bad ttl, and :class:`NotConnectedError` when not connected (the reading is not sent; a
        sensing loop catches it and goes on).
        """
        check_lengths("sensor", sensor=sensor)
        message = {"type": "sensor", "sensor": sensor, "source": self.name,
                   "values": [value_to_json(v, "Value %d of sensor '%s'" % (i + 1, sensor)) for i, v in enumerate(values)]}
        if ttl is not None:
            ms = round(ttl * 1000)
            if isinstance(ttl, bool) or abs(ms - ttl * 1000) > 1e-6 or not 1 <= ms <= _MAX_TTL_MS:
                raise ValueError("The time to live of sensor '%s' must be a whole number of milliseconds from 0.001 s "
                                 "to a day (86400 s), not %r s." % (sensor, ttl))
            message["ttlMs"] = ms
        self._send(message)

    def query(self, of_class, timeout=None):
        """Every instance of a class (and of the classes below it), as :class:`Frame` s."""
        check_lengths("query", of_class=of_class)
        answer = self._request({"type": "query", "ofClass": of_class}, "frames", "the query of class '%s'" % of_class,
                               timeout)
        return [Frame.parse(xml) for xml in answer["frames"]]

    def ask(self, frame, slot, timeout=None):
        """The effective value of a slot, inherited along IS-A; None when it has none."""
        answer = self._request({"type": "ask", "frame": frame, "slot": slot}, "answer",
                               "the ask for slot '%s' of frame '%s'" % (slot, frame), timeout)
        return value_from_json(answer["value"]) if answer.get("value") is not None else None

    def prove(self, of_class, bindings=None, timeout=None):
        """Backward chaining on the server: every instance of ``of_class`` that exists or could be derived, whose
        slots hold the instances ``bindings`` names (slot to instance), each a :class:`ProofNode`. Nothing is created."""
        check_lengths("prove", of_class=of_class)
        answer = self._request({"type": "prove", "ofClass": of_class, "bindings": dict(bindings or {})}, "proofs",
                               "the proof of class '%s'" % of_class, timeout)
        return [ProofNode.from_json(p) for p in answer["proofs"]]

    def why(self, instance, timeout=None):
        """Why an instance exists, back to the stimuli: a :class:`Reason`."""
        answer = self._request({"type": "why", "instance": instance}, "explained",
                               "the why of instance '%s'" % instance, timeout)
        return Reason.from_json(answer["reason"])

    def why_not(self, frame, bindings=None, timeout=None):
        """Why a behavior frame has not fired, with the required slots ``bindings`` names held: a :class:`NotFired`."""
        answer = self._request({"type": "why_not", "frame": frame, "bindings": dict(bindings or {})}, "not_fired",
                               "the why-not of frame '%s'" % frame, timeout)
        return NotFired.from_json(answer)

    def assert_frames(self, *frames, timeout=None):
        """Adds or replaces instance frames (XML), stored as RUNTIME frames in one batch: the server takes all or none."""
        if not frames:
            raise ValueError("Nothing to assert: no frames given.")
        text = frames[0] if len(frames) == 1 else "<KNOWLEDGEBASE>%s</KNOWLEDGEBASE>" % "".join(frames)
        self._request({"type": "assert", "frame": text}, "ack", "the assert of %d frame(s)" % len(frames), timeout)

    def destroy(self, frame, timeout=None):
        """Removes a RUNTIME instance (with what the engine derived from it, in the platform)."""
        self._request({"type": "destroy", "frame": frame}, "ack", "the destroy of frame '%s'" % frame, timeout)

    def push(self, *frames, timeout=None):
        """Sends frames (XML, parents first) to the server, as a peer platform shares knowledge: stored all or none."""
        if not frames:
            raise ValueError("Nothing to push: no frames given.")
        self._request({"type": "push", "frames": list(frames)}, "ack", "the push of %d frame(s)" % len(frames), timeout)

    def pull(self, root=None, timeout=None):
        """A subtree of the server's knowledge base (the whole of it without ``root``) as :class:`Frame` s, parents
        first and RUNTIME frames left out."""
        message = {"type": "pull"} if root is None else {"type": "pull", "root": root}
        answer = self._request(message, "frames", "the pull of %s" % ("the knowledge base" if root is None
                                                                     else "the subtree of '%s'" % root), timeout)
        return [Frame.parse(xml) for xml in answer["frames"]]

    def subscribe(self, of_class, callback=None, timeout=None):
        """Hears of every change to frames of ``of_class`` (and below): ``callback(change)`` with a :class:`Changed`,
        or :meth:`on_changed` without one, on the event thread. Renewed by itself after a reconnect."""
        check_lengths("subscribe", of_class=of_class)
        self._request({"type": "subscribe", "ofClass": of_class}, "ack", "the subscription to class '%s'" % of_class,
                      timeout)
        with self._lock:
            if of_class not in self._subscriptions:
                self._subscriptions.append(of_class)
            if callback is not None:
                self._callbacks[of_class] = callback

    def unsubscribe(self, of_class, timeout=None):
        """Stops the notifications of a class."""
        check_lengths("unsubscribe", of_class=of_class)
        with self._lock:
            if of_class in self._subscriptions:
                self._subscriptions.remove(of_class)
            self._callbacks.pop(of_class, None)
        self._request({"type": "unsubscribe", "ofClass": of_class}, "ack",
                      "the unsubscription from class '%s'" % of_class, timeout)

    def relay_to(self, agent, subject, body, timeout=None):
        """Relays a message to one agent by name and waits for the hub's ``ack`` (``unknown_agent`` when it is not there)."""
        self._request(self._relay("relay_to", agent, None, subject, body), "ack", "the relay to agent '%s'" % agent,
                      timeout)

    def relay_to_kind(self, kind, subject, body, timeout=None):
        """Relays a message to every registered agent of a kind (not to this one) and waits for the ``ack``."""
        kind = AgentKind(kind)
        self._request(self._relay("relay_to_kind", None, kind, subject, body), "ack",
                      "the relay to every %s" % kind.value, timeout)

    def tell_to(self, agent, subject, body):
        """Relays a message to one agent without waiting (fire and forget); a refusal comes later and is logged."""
        self._send(dict(self._relay("tell_to", agent, None, subject, body), id=""))

    def tell_to_kind(self, kind, subject, body):
        """Relays a message to every agent of a kind without waiting, as :meth:`tell_to`."""
        self._send(dict(self._relay("tell_to_kind", None, AgentKind(kind), subject, body), id=""))

    def command(self, robot, action, args=None, timeout=None):
        """Sends a command to a robot through the hub (what a user agent does); follow it with the :class:`CommandTicket`."""
        check_lengths("command", robot=robot, action=action)
        command = Command(self._command_id(), robot, action, {str(k): str(v) for k, v in (args or {}).items()})
        ticket = CommandTicket(command)
        with self._lock:
            self._tickets[command.id] = ticket
        try:
            self._request({"type": "command", "id": command.id, "robot": robot, "action": action,
                           "args": command.args}, "ack", "command '%s' (%s) to robot '%s'" % (command.id, action, robot),
                          timeout)
        except AgentError:
            with self._lock:
                self._tickets.pop(command.id, None)
            raise
        return ticket

    def cancel(self, robot, command_id, reason="", timeout=None):
        """Asks that a command in flight on a robot be stopped (a user or service agent); the outcome is the command's
        last feedback. Raises :class:`RequestRefusedError` when no such command is in flight or this agent may not."""
        check_lengths("cancel", robot=robot, command_id=command_id)
        self._request({"type": "cancel", "robot": robot, "command": command_id, "reason": reason}, "ack",
                      "the cancel of command '%s' on robot '%s'" % (command_id, robot), timeout)

    # ---- internals ----

    def _command_id(self):
        """The agent's name, the time this object was made and a counter, as the Java SDK makes it: a name so long that
        the id would pass the server's limit gives only its beginning (the server refuses a clash, never mixes up)."""
        tail = "-%s-%d" % (self._command_ids, next(self._ids))
        head = self.name
        while length(head) + len(tail) > MAX_NAME_LENGTH:
            head = head[:-1]
        return head + tail

    def _relay(self, call, agent, kind, subject, body):
        check_lengths(call, agent=agent, subject=subject)
        message = {"type": "relay", "from": self.name, "subject": subject, "body": body}
        if agent is not None:
            message["toAgent"] = agent
        else:
            message["toKind"] = kind.value
        return message

    def _run_command(self, command, handle):
        handler = self._actions.get(command.action)
        if handler is None:
            self.on_command(command, handle)
            return
        handle.started()
        result = handler(command, handle)
        if not handle.is_done and not handle.cancel_requested:  # after a cancel, on_cancel reports the end
            handle.ended("" if result is None else str(result))

    def _send_feedback(self, feedback):
        message = {"type": "feedback", "id": feedback.id, "robot": feedback.robot, "stage": feedback.stage,
                   "detail": feedback.detail}
        if feedback.progress is not None:
            message["progress"] = feedback.progress
        self._send(message)

    def _send(self, message):
        """Sends a message that expects no answer; NotConnectedError when there is no connection or it fails."""
        connection = self._connection
        if connection is None:
            raise NotConnectedError("Agent '%s' is not connected; the %s message was not sent."
                                    % (self.name, message["type"]))
        try:
            connection.send(message)
        except OSError as e:
            connection.close()
            raise NotConnectedError("Agent '%s' could not send the %s message: %s" % (self.name, message["type"],
                                                                                     _sentence(str(e)))) from e

    def _request(self, message, expected, what, timeout):
        """Sends a request with a fresh id and waits for its answer, which must be ``expected`` or an error."""
        message = dict(message, id=message.get("id") or str(next(self._ids)))
        limit = self.options.request_timeout if timeout is None else timeout
        answer = self._pending.call(message["id"], lambda: self._send(message), limit)
        if answer is None:
            raise AgentTimeoutError("The server did not answer %s (request '%s') within %g s."
                                    % (what, message["id"], limit))
        if answer["type"] == "error":
            raise RequestRefusedError(answer["code"], "The server refused %s (%s): %s"
                                      % (what, answer["code"], answer["message"]))
        if answer["type"] != expected:
            raise ProtocolError("The server answered %s with a %s message, not %s." % (what, answer["type"], expected))
        return answer

    def _supervise(self):
        delay = self.options.backoff_initial
        while not self._closed.is_set():
            connection = None
            fatal = None
            try:
                connection = Connection.open(self.options)
                if self._closed.is_set():  # closed while connecting
                    return
                self._handshake(connection)
                delay = self.options.backoff_initial
                self._read_loop(connection)
            except AuthenticationError as e:
                fatal = (e, None)
                return
            except (OSError, ProtocolError) as e:
                if self._closed.is_set():
                    return
                self._last_failure = str(e) or type(e).__name__
                LOG.info("Agent '%s' lost its connection to %s:%d (%s); reconnecting.", self.name, self.options.host,
                         self.options.port, self._last_failure)
            except Exception as e:  # a bug in the program (say, in capabilities()) or a server we do not understand
                fatal = (AgentError("Agent '%s' failed: %s" % (self.name, _sentence("%s: %s" % (type(e).__name__, e)))),
                         e)
                return
            finally:
                if connection is not None:
                    connection.close()
                self._lost()
                if fatal is not None:  # only now: whoever sees `stopped` set sees the agent disconnected too
                    self._stop(*fatal)
            if self._closed.wait(delay / 2 + random.uniform(0, delay / 2)):  # "equal jitter"
                return
            delay = min(delay * 2, self.options.backoff_max)

    def _stop(self, error, cause=None):
        self._fatal = error
        LOG.error("%s The agent stops.", error, exc_info=cause)

    def _handshake(self, connection):
        connection.send({"type": "hello", "id": "hello", "agent": self.name, "kind": self.kind.value,
                         "token": self.options.token})
        auth = self._await_direct(connection, "hello")
        if auth["type"] == "error" or not auth["accepted"]:
            reason = auth.get("message") or auth.get("reason") or "no reason given"
            raise AuthenticationError("The server refused agent '%s' (kind %s): %s"
                                      % (self.name, self.kind.value, _sentence(reason)))
        connection.send({"type": "register", "id": "register", "capabilities": self.capabilities()})
        registered = self._await_direct(connection, "register")
        if registered["type"] == "error":
            raise AuthenticationError("The server refused to register agent '%s' (%s): %s"
                                      % (self.name, registered["code"], _sentence(registered["message"])))
        self._connection = connection
        with self._lock:
            subscriptions = list(self._subscriptions)
        for of_class in subscriptions:
            connection.send({"type": "subscribe", "id": "resubscribe-%d" % next(self._ids), "ofClass": of_class})
        self._registered.set()
        self._start_heartbeats(connection)
        LOG.info("Agent '%s' registered with %s:%d.", self.name, self.options.host, self.options.port)
        self._events.put(self.on_connected)

    def _await_direct(self, connection, request_id):
        while True:
            message = connection.read()
            if message["type"] in ("auth_result", "ack") and message["id"] == request_id:
                return message
            if message["type"] == "error" and message.get("id", request_id) in (request_id, ""):
                return message
            # heartbeats may come before registration

    def _start_heartbeats(self, connection):
        interval = self.options.heartbeat_interval

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

        threading.Thread(target=beat, name="agent-heartbeat-" + self.name, daemon=True).start()

    def _read_loop(self, connection):
        while not self._closed.is_set():
            m = connection.read()
            kind = m["type"]
            if kind == "command":
                self._runner.command(Command(m["id"], m["robot"], m["action"], dict(m["args"])))
            elif kind == "cancel":
                self._runner.cancel(m["command"], m["reason"])
            elif kind == "feedback":
                self._feedback(Feedback(m["id"], m["robot"], m["stage"], m["detail"], m.get("progress")))
            elif kind == "relay":
                relay = Relay(m["id"], m["from"], m["subject"], m["body"], m.get("toAgent"), m.get("toKind"))
                self._events.put(functools.partial(self.on_relay, relay))
            elif kind == "changed":
                values = m.get("values")
                change = Changed(m["ofClass"], m["change"], m["name"], m.get("frame"),
                                 None if values is None else value_from_json(values))
                self._events.put(functools.partial(self._changed, change))
            elif kind == "error":
                self._error(m)
            elif kind != "heartbeat":
                self._complete(m)

    def _error(self, m):
        if m["code"] == "superseded":
            raise AuthenticationError("Agent '%s' was replaced by a newer connection under its name: %s"
                                      % (self.name, _sentence(m["message"])))
        if m.get("id"):
            self._complete(m)
            return
        LOG.warning("Agent '%s': the server says %s: %s", self.name, m["code"], m["message"])
        if m["code"] in _CLOSING:
            self._closing_error = m

    def _complete(self, answer):
        if not self._pending.answer(answer) and answer["type"] == "error":
            LOG.warning("Agent '%s': request '%s' was refused (%s): %s", self.name, answer["id"], answer["code"],
                        answer["message"])

    def _feedback(self, feedback):
        with self._lock:
            ticket = self._tickets.pop(feedback.id, None) if feedback.terminal else self._tickets.get(feedback.id)
        if ticket is not None:
            ticket._received(feedback)

    def _changed(self, change):
        with self._lock:
            callback = self._callbacks.get(change.of_class)
        (callback or self.on_changed)(change)

    def _lost(self):
        was = self._registered.is_set()
        self._registered.clear()
        self._connection = None
        why, self._closing_error = self._closing_error, None
        if self._closed.is_set():
            self._pending.fail_all(NotConnectedError("Agent '%s' was closed." % self.name))
        elif why is not None and why["code"] == "frame_too_large":
            # The request in flight was too long for the server, which said so and closed: that is its answer.
            self._pending.fail_all(RequestRefusedError(why["code"], why["message"]))
        else:
            self._pending.fail_all(NotConnectedError(
                "Agent '%s' lost its connection%s" % (self.name, "." if why is None else ": the server closed it (%s): %s"
                                                       % (why["code"], _sentence(why["message"])))))
        with self._lock:
            tickets, self._tickets = self._tickets, {}
        for command_id, ticket in tickets.items():  # the server sends feedback to the connection that sent a command
            ticket._received(Feedback(command_id, ticket.command.robot, "failed",
                                      "the connection to the gateway was lost before command '%s' ended" % command_id))
        self._runner.connection_lost("agent '%s' was closed" % self.name if self._closed.is_set()
                                     else "the connection to the gateway was lost")
        if was and not self._closed.is_set():
            self._events.put(lambda: self.on_disconnected("connection lost"))


def _sentence(text):
    """Text as the end of a sentence: with a full stop, unless it has one."""
    text = text.strip()
    return text if text.endswith((".", "!", "?")) else text + "."


def _base36(number):
    digits = "0123456789abcdefghijklmnopqrstuvwxyz"
    out = ""
    while number:
        number, rest = divmod(number, 36)
        out = digits[rest] + out
    return out or "0"
