"""How what the reader thread receives reaches the program: answers to the requests waiting for them
(:class:`PendingRequests`), and relays, changes and connection news in order on one thread (:class:`EventQueue`)."""
import logging
import queue
import threading

from .errors import NotConnectedError

LOG = logging.getLogger("kicnp_agent")


class PendingRequests:
    """The requests waiting for their answers, by id. The reader hands each answer to its waiter; a lost connection
    fails them all with one error."""

    def __init__(self):
        self._waiting = {}
        self._lock = threading.Lock()

    def call(self, request_id, send, timeout):
        """Waits for the answer to ``request_id`` after ``send()``: the answer, None after ``timeout`` seconds, or the
        error that failed every request waiting."""
        waiter = _Waiter()
        with self._lock:
            self._waiting[request_id] = waiter
        try:
            try:
                send()
            except NotConnectedError as e:
                # The connection failed under the write. A request longer than the server's frame limit is refused as
                # soon as its length is read, and the server closes after saying so, often before the rest is written:
                # the reader then hears the refusal and fails every waiting request with the server's reason, which
                # says more than the closed socket. Not connected at all (no OSError): nobody will answer.
                if not isinstance(e.__cause__, OSError) or not waiter.done.wait(timeout):
                    raise
            if not waiter.done.wait(timeout):
                return None
            if waiter.error is not None:
                raise waiter.error
            return waiter.answer
        finally:
            with self._lock:
                self._waiting.pop(request_id, None)

    def answer(self, message):
        """Hands an answer to the request it names; False when none waits for it (it timed out, or never was)."""
        with self._lock:
            waiter = self._waiting.get(message["id"])
        if waiter is None:
            return False
        waiter.answer = message
        waiter.done.set()
        return True

    def fail_all(self, error):
        with self._lock:
            waiters, self._waiting = list(self._waiting.values()), {}
        for waiter in waiters:
            waiter.error = error
            waiter.done.set()


class _Waiter:
    """A request's answer, or the error that ended the wait."""

    def __init__(self):
        self.done = threading.Event()
        self.answer = None
        self.error = None


class EventQueue:
    """Calls made in order on one thread of their own. Bounded: when it is full, ``put`` waits, so the reader stops
    reading and TCP pushes back on the server (which sheds, then drops a connection that does not read)."""

    def __init__(self, agent, closed, size=10000):
        self._agent = agent
        self._closed = closed
        self._calls = queue.Queue(size)

    def put(self, call):
        """Queues a call; returns without it once the agent is closed."""
        while not self._closed.is_set():
            try:
                self._calls.put(call, timeout=0.1)
                return
            except queue.Full:
                continue

    def run(self):
        """Makes the calls until the agent is closed and none is left; a call that raises is logged."""
        while True:
            try:
                call = self._calls.get(timeout=0.1)
            except queue.Empty:
                if self._closed.is_set():
                    return
                continue
            try:
                call()
            except Exception:
                LOG.exception("Agent '%s': a relay, change or connection handler failed.", self._agent)
