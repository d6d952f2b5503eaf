"""Commands: how a robot reports on one (:class:`ActionHandle`), how commands run (:class:`CommandRunner`), and how
a user agent follows one it sent (:class:`CommandTicket`). The Python side of section 3.3 of the paper: robots
"send back" the feedback of their actions.
"""
import logging
import math
import threading

from .errors import ActionFailedError, AgentTimeoutError, NotConnectedError
from .messages import Feedback

LOG = logging.getLogger("kicnp_agent")


class ActionHandle:
    """How a robot reports on one command: ``started()``, any number of ``progress``, then one of ``ended``,
    ``failed`` or ``cancelled``. Usable from any thread, also after the handler returned.

    A cancel asked for while the command runs sets :attr:`cancel_requested` (a long command checks it between its
    steps, or waits on :meth:`wait_cancelled` instead of sleeping). Once the command was reported cancelled, or the
    connection it came on was lost (the gateway has failed it already), later reports are ignored.
    """

    def __init__(self, command, send):
        self.command = command
        self._send = send
        self._lock = threading.Lock()
        self._started = False
        self._done = False
        self._cut_off = False
        self._reported_cancelled = False
        self._cancel_reason = None
        self._cancel = threading.Event()

    def started(self):
        """Reports that the command started; only once (the SDK reports it before an action handler runs)."""
        with self._lock:
            if self._started or self._done or self._cut_off:
                return
            self._started = True
        self._report("started", "")

    def progress(self, fraction, note=""):
        """Reports progress: the fraction done, 0.0 to 1.0, and a note; a ValueError (nothing sent) otherwise."""
        if isinstance(fraction, bool) or not isinstance(fraction, (int, float)) or math.isnan(fraction) \
                or not 0.0 <= fraction <= 1.0:
            raise ValueError("The progress of command '%s' must be a number from 0.0 to 1.0, not %r."
                             % (self.command.id, fraction))
        with self._lock:
            if self._silenced_or_done("progress"):
                return
        self._report("progress", note, float(fraction))

    def ended(self, result=""):
        """The command ended; ``result`` says what came of it."""
        self._finish("ended", result)

    def failed(self, reason):
        """The command failed; ``reason`` says why, for people."""
        self._finish("failed", reason)

    def cancelled(self, reason):
        """Reports the command stopped because it was cancelled: ``failed`` with ``cancelled: REASON``."""
        with self._lock:
            if self._done:
                return
            self._done = True
            self._reported_cancelled = True
            if self._cut_off:
                return
        self._send(Feedback(self.command.id, self.command.robot, "failed", "cancelled: " + reason))

    @property
    def cancel_requested(self):
        """Whether a cancel was asked for (by a user, the platform, or the loss of the connection)."""
        return self._cancel.is_set()

    @property
    def cancel_reason(self):
        """Why a cancel was asked for, or None."""
        return self._cancel_reason

    def wait_cancelled(self, timeout):
        """Waits up to ``timeout`` seconds for a cancel; True if one was asked for. A robot's loop sleeps with it."""
        return self._cancel.wait(timeout)

    @property
    def is_done(self):
        """Whether the command was reported ended, failed or cancelled."""
        return self._done

    def _request_cancel(self, reason):
        """Records the first cancel; False for a later one, which the agent's ``on_cancel`` does not hear again."""
        with self._lock:
            if self._cancel_reason is not None:
                return False
            self._cancel_reason = reason
        self._cancel.set()
        return True

    def _cut(self):
        """The connection the command came on is gone: later reports go nowhere, and are dropped."""
        with self._lock:
            self._cut_off = True

    def _silenced_or_done(self, stage):
        """Under the lock: True when a report is to be dropped; a RuntimeError when it comes after the end."""
        if self._reported_cancelled:
            return True
        if self._done:
            if self._cancel_reason is not None:
                return True  # the cancel reported the end; the robot's program is still winding down
            raise RuntimeError("Command '%s' was already reported done; no more %s reports." % (self.command.id, stage))
        return self._cut_off

    def _finish(self, stage, detail):
        if not isinstance(detail, str):
            raise TypeError("The %s detail of command '%s' must be a str, not %s."
                            % (stage, self.command.id, type(detail).__name__))
        with self._lock:
            if self._silenced_or_done(stage):
                self._done = True
                return
            self._done = True
        self._send(Feedback(self.command.id, self.command.robot, stage, detail))

    def _report(self, stage, note, fraction=None):
        self._send(Feedback(self.command.id, self.command.robot, stage, note, fraction))


class CommandRunner:
    """Runs each command on a thread of its own through ``run(command, handle)`` and keeps the commands in flight,
    so that a cancel finds its handle and runs ``on_cancel(handle, reason)`` once.

    A handler that raises ends its command as failed, with the exception's message, rather than leave it in flight
    for good; a lost connection cancels every command in flight, since the server fails them and will not hear of
    them again.
    """

    def __init__(self, agent, run, on_cancel, send):
        self._agent = agent
        self._run_command = run
        self._on_cancel = on_cancel
        self._send = send
        self._running = {}
        self._lock = threading.Lock()

    @property
    def in_flight(self):
        with self._lock:
            return len(self._running)

    def command(self, command):
        """Starts a command from the server on a thread of its own; returns at once."""
        handle = ActionHandle(command, lambda feedback: self._report(command.id, feedback))
        with self._lock:
            self._running[command.id] = handle
        self._thread("command-" + command.id, self._run, command, handle)

    def cancel(self, command_id, reason):
        """Asks a running command to stop: ``on_cancel`` runs unless it is not running or is being cancelled."""
        with self._lock:
            handle = self._running.get(command_id)
        if handle is None or handle.is_done:
            LOG.debug("Agent '%s': cancel of '%s', which is not running.", self._agent, command_id)
        elif not handle._request_cancel(reason):
            LOG.debug("Agent '%s': '%s' is already being cancelled.", self._agent, command_id)
        else:
            self._thread("cancel-" + command_id, self._cancel, handle, reason)

    def connection_lost(self, reason):
        """Cuts off every command in flight and cancels it with ``reason``, so the robot stops and its program hears."""
        with self._lock:
            handles = list(self._running.values())
            self._running.clear()
        for handle in handles:
            handle._cut()
            if not handle.is_done and handle._request_cancel(reason):
                LOG.info("Agent '%s' cancels command '%s': %s.", self._agent, handle.command.id, reason)
                self._thread("cancel-" + handle.command.id, self._cancel, handle, reason)

    def _report(self, command_id, feedback):
        if feedback.terminal:
            with self._lock:
                self._running.pop(command_id, None)
        try:
            self._send(feedback)
        except NotConnectedError as e:
            # The connection is going: its loss cancels the command, which is how the robot's program hears of it.
            LOG.debug("Agent '%s' could not report on '%s': %s", self._agent, command_id, e)

    def _run(self, command, handle):
        try:
            self._run_command(command, handle)
        except NotConnectedError:
            LOG.info("Agent '%s' lost its connection during command '%s'; the server fails it.", self._agent, command.id)
        except Exception as e:
            LOG.warning("Agent '%s' failed on command '%s'.", self._agent, command.id, exc_info=True)
            if not handle.is_done and not handle.cancel_requested:  # after a cancel, on_cancel reports the end
                handle.failed("Agent '%s' failed on '%s': %s" % (self._agent, command.action, _say(e)))

    def _cancel(self, handle, reason):
        try:
            self._on_cancel(handle, reason)
        except NotConnectedError:
            LOG.info("Agent '%s' lost its connection while cancelling '%s'.", self._agent, handle.command.id)
        except Exception as e:
            LOG.warning("Agent '%s' failed to cancel '%s'.", self._agent, handle.command.id, exc_info=True)
            # Not "cancelled": the robot may still be moving, and whoever asked it to stop must know.
            if not handle.is_done:
                handle.failed("cancel failed: %s (agent '%s', asked to stop: %s); the robot may not have stopped"
                              % (_say(e), self._agent, reason))

    @staticmethod
    def _thread(name, target, *args):
        threading.Thread(target=target, args=args, name=name, daemon=True).start()


def _say(error):
    """An exception as a sentence's part: its type and message (the message alone may be empty)."""
    text = str(error)
    return "%s: %s" % (type(error).__name__, text) if text else type(error).__name__


class CommandTicket:
    """A command a user agent sent: the feedback so far, and its outcome once it ends or fails."""

    def __init__(self, command):
        self.command = command
        self._feedback = []
        self._lock = threading.Lock()
        self._outcome = None
        self._ended = threading.Event()

    @property
    def feedback(self):
        """Every feedback received so far, in order."""
        with self._lock:
            return list(self._feedback)

    def result(self, timeout):
        """Waits up to ``timeout`` seconds for the command to end and returns its result.

        Raises :class:`ActionFailedError` with the robot's reason when it failed, :class:`AgentTimeoutError` when it
        has not ended in time.
        """
        if not self._ended.wait(timeout):
            raise AgentTimeoutError("Command '%s' (%s) to robot '%s' did not end within %g s."
                                    % (self.command.id, self.command.action, self.command.robot, timeout))
        if self._outcome.stage == "failed":
            raise ActionFailedError("Command '%s' (%s) to robot '%s' failed: %s"
                                    % (self.command.id, self.command.action, self.command.robot, self._outcome.detail))
        return self._outcome.detail

    def _received(self, feedback):
        with self._lock:
            self._feedback.append(feedback)
            if feedback.terminal and self._outcome is None:
                self._outcome = feedback
                self._ended.set()
