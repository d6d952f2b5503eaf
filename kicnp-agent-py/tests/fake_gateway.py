"""A gateway stand-in on a socket of the test's own, for what a real gateway will not do on cue: stay silent, drop a
connection in the middle of a request, close with an error, or send what is not the protocol."""
import json
import socket
import struct
import threading


class FakeGateway:
    """Accepts agents one connection after another, authenticates and registers each, keeps every message it
    receives, and hands the others to ``answer(gateway, message)`` (by default: no answer)."""

    def __init__(self, answer=None, before_register_answer=(), refuse_longer_than=None):
        self._before_register_answer = list(before_register_answer)  # sent ahead of the ack, as no gateway should
        self._refuse_longer_than = refuse_longer_than
        self._released = threading.Event()
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.received = []
        self.connections = 0
        self._answer = answer or (lambda gateway, message: None)
        self._conn = None
        self._lock = threading.Lock()
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self):
        while True:
            try:
                conn, _ = self.listener.accept()
            except OSError:
                return
            with self._lock:
                self._conn = conn
                self.connections += 1
            with conn:
                self._read_all(conn)

    def _read_all(self, conn):
        try:
            while True:
                header = conn.recv(4, socket.MSG_WAITALL)
                length = struct.unpack(">I", header)[0]
                if self._refuse_longer_than is not None and length > self._refuse_longer_than:
                    self._refuse(conn, length)
                    return
                message = json.loads(conn.recv(length, socket.MSG_WAITALL))
                self.received.append(message)
                if message["type"] == "hello":
                    self.send({"type": "auth_result", "id": message["id"], "accepted": True, "server": "fake"})
                elif message["type"] == "register":
                    for early in self._before_register_answer:
                        self.send(early)
                    self.send({"type": "ack", "id": message["id"]})
                else:
                    self._answer(self, message)
        except (OSError, struct.error, ValueError):
            return

    def _refuse(self, conn, length):
        """As the gateway refuses a frame for its length: says so at once and ends what it sends, but here reads
        nothing more and keeps the connection open until the test is over, so the agent's write of it cannot finish."""
        self.send({"type": "error", "code": "frame_too_large",
                   "message": "A frame of %d bytes is longer than this server accepts (%d bytes at most)."
                   % (length, self._refuse_longer_than)})
        conn.shutdown(socket.SHUT_WR)
        self._released.wait(30)

    def send(self, message, version=1):
        self.send_bytes(json.dumps(dict(message, v=version)).encode())

    def send_bytes(self, payload):
        with self._lock:
            self._conn.sendall(struct.pack(">I", len(payload)) + payload)

    def send_raw(self, data):
        """Writes bytes as they are, without a length of their own: a length that lies, or a frame cut short."""
        with self._lock:
            self._conn.sendall(data)

    def drop(self):
        """Closes the agent's current connection, as a crashed server or a cut cable would."""
        with self._lock:
            self._conn.shutdown(socket.SHUT_RDWR)

    def close(self):
        self._released.set()
        try:
            self.listener.shutdown(socket.SHUT_RDWR)  # wakes the thread waiting in accept
        except OSError:
            pass  # not supported here: closing is enough to refuse new agents
        self.listener.close()
