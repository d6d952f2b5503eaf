"""The agent: the Python counterpart of org.kicnp.agent.AgentBase, the paper's "Agent Base Classes"."""
import itertools
import logging
import threading
import time

from .actions import CommandRunner, CommandTicket
from .dispatch import EventQueue, PendingRequests
from .errors import AgentError, AgentTimeoutError, NotConnectedError, ProtocolError, RequestRefusedError
from .frames import Frame
from .messages import Command, Feedback, NotFired, ProofNode, Reason, Snapshot, value_from_json, value_to_json
from .options import AgentKind, AgentOptions
from .supervisor import Supervisor, _sentence
from .wire import MAX_NAME_LENGTH, check_lengths, length

LOG = logging.getLogger("kicnp_agent")
_MAX_TTL_MS = 86400000


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
        # The connection's life: connect, register, heartbeats, read, reconnect (see supervisor.py).
        self._supervisor = Supervisor(self, self._pending, self._events, self._runner, self._closed, self._ids)
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
        return self._supervisor.registered.is_set()

    @property
    def commands_in_flight(self):
        """How many commands this robot took and has neither reported done nor lost with its connection."""
        return self._runner.in_flight

    @property
    def stopped(self):
        """Why the agent stopped for good (refused, or replaced by a newer connection), or None while it runs."""
        return self._supervisor.fatal

    def start(self):
        """Starts connecting in the background and returns at once; see :meth:`wait_connected`."""
        if self._threads:
            raise RuntimeError("Agent '%s' was already started." % self.name)
        for name, target in (("agent-" + self.name, self._supervisor.run), ("agent-events-" + self.name, self._events.run)):
            thread = threading.Thread(target=target, name=name, daemon=True)
            self._threads.append(thread)
            thread.start()
        return self

    def wait_connected(self, timeout):
        """Waits until the agent is registered; raises :class:`AuthenticationError` when the server refused it,
        :class:`AgentTimeoutError` (naming the last failure) when it is not registered within ``timeout`` seconds."""
        supervisor = self._supervisor
        deadline = time.monotonic() + timeout
        while not supervisor.registered.is_set() and supervisor.fatal is None and not self._closed.is_set():
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                break
            supervisor.registered.wait(min(0.05, remaining))
        if supervisor.fatal is not None:
            raise supervisor.fatal
        if not supervisor.registered.is_set():
            last = supervisor.last_failure
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
                if self._supervisor.fatal is not None:
                    raise self._supervisor.fatal
        except KeyboardInterrupt:
            LOG.info("Agent '%s' interrupted; closing.", self.name)
        finally:
            self.close()

    def close(self):
        """Disconnects for good: commands in flight are cancelled and requests waiting fail with NotConnectedError."""
        self._closed.set()
        connection = self._supervisor.connection
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
        return self.snapshot(of_class, timeout).frames

    def snapshot(self, of_class, timeout=None):
        """As :meth:`query`, with the server's clock when it read the frames: a :class:`Snapshot`. The times the
        frames hold (a sensor signal's ``time`` and ``expires``) are on that clock, which need not be this machine's."""
        check_lengths("query", of_class=of_class)
        answer = self._request({"type": "query", "ofClass": of_class}, "frames", "the query of class '%s'" % of_class,
                               timeout)
        return Snapshot([Frame.parse(xml) for xml in answer["frames"]], answer.get("time"))

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
        connection = self._supervisor.connection
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

    def _feedback(self, feedback):
        with self._lock:
            ticket = self._tickets.pop(feedback.id, None) if feedback.terminal else self._tickets.get(feedback.id)
        if ticket is not None:
            ticket._received(feedback)

    def _changed(self, change):
        with self._lock:
            callback = self._callbacks.get(change.of_class)
        (callback or self.on_changed)(change)

    def _subscribed(self):
        """The classes subscribed to, for the supervisor to renew on a new connection."""
        with self._lock:
            return list(self._subscriptions)

    def _commands_lost(self):
        """The connection is lost: the server sends feedback to the connection that sent a command, so each fails."""
        with self._lock:
            tickets, self._tickets = self._tickets, {}
        for command_id, ticket in tickets.items():
            ticket._received(Feedback(command_id, ticket.command.robot, "failed",
                                      "the connection to the gateway was lost before command '%s' ended" % command_id))


def _base36(number):
    digits = "0123456789abcdefghijklmnopqrstuvwxyz"
    out = ""
    while number:
        number, rest = divmod(number, 36)
        out = digits[rest] + out
    return out or "0"
