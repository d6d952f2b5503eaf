"""One connection to a gateway: framed messages over plain TCP or TLS, read by one thread, written by any.

TLS runs through ``ssl.SSLObject`` and memory buffers rather than ``SSLSocket``: one OpenSSL object must not be
used by two threads at once, and here the reader waits on the socket while commands and heartbeats write. The TLS
state is touched only under a lock and never while waiting for the network, so a write does not wait for a read.
"""
import socket
import ssl
import threading
import time

from . import wire

_RECEIVE = 65536


class _Plain:
    """The socket as it is."""

    def __init__(self, sock):
        self.sock = sock
        self._lock = threading.Lock()

    def send(self, data):
        with self._lock:
            self.sock.sendall(data)

    def receive(self):
        return self.sock.recv(_RECEIVE)


class _Tls:
    """TLS over the socket, the server checked against the certificate(s) of ``context`` and ``server_name``."""

    def __init__(self, sock, context, server_name):
        self.sock = sock
        self._in = ssl.MemoryBIO()
        self._out = ssl.MemoryBIO()
        self._tls = context.wrap_bio(self._in, self._out, server_hostname=server_name)
        self._lock = threading.Lock()
        self._handshake()

    def _handshake(self):
        while True:
            try:
                self._tls.do_handshake()
                self._flush()
                return
            except ssl.SSLWantReadError:
                self._flush()
                data = self.sock.recv(_RECEIVE)
                if not data:
                    raise ConnectionError("The server closed the connection during the TLS handshake.")
                self._in.write(data)

    def _flush(self):
        pending = self._out.read()
        if pending:
            self.sock.sendall(pending)

    def send(self, data):
        with self._lock:
            self._tls.write(data)
            self._flush()

    def receive(self):
        while True:
            data = self.sock.recv(_RECEIVE)
            with self._lock:
                if not data:
                    self._in.write_eof()
                else:
                    self._in.write(data)
                plain = bytearray()
                try:
                    while True:
                        plain += self._tls.read(_RECEIVE)
                except ssl.SSLWantReadError:
                    pass
                except ssl.SSLZeroReturnError:
                    return bytes(plain)
                self._flush()  # what TLS itself answers (key updates)
            if plain or not data:
                return bytes(plain)


class Connection:
    """A connected, framed channel to a gateway. ``read`` is for one thread; ``send`` for any."""

    def __init__(self, transport, options):
        self._transport = transport
        self._options = options
        self._frames = wire.FrameBuffer(options.max_frame_bytes)
        self._closed = False
        self.last_sent = time.monotonic()

    @staticmethod
    def open(options):
        """Connects (TLS when ``options.tls_trust`` names a certificate); waits ``server_silence`` for each read."""
        sock = socket.create_connection((options.host, options.port), timeout=options.request_timeout)
        try:
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            if options.tls_trust is None:
                transport = _Plain(sock)
            else:
                context = ssl.create_default_context(cafile=options.tls_trust)
                transport = _Tls(sock, context, options.tls_server_name or options.host)
            sock.settimeout(options.server_silence)
            return Connection(transport, options)
        except BaseException:
            sock.close()
            raise

    def send(self, message):
        """Writes one message (a dict with ``type``); an ``OSError`` when the connection fails."""
        data = wire.encode(message, self._options.max_frame_bytes)
        if self._closed:
            raise ConnectionError("The connection is closed.")
        self._transport.send(data)
        self.last_sent = time.monotonic()

    def read(self):
        """Waits for the next message; ``ConnectionError`` when the server closes or stays silent too long."""
        while True:
            payload = self._frames.next_frame()
            if payload is not None:
                return wire.decode(payload)
            try:
                data = self._transport.receive()
            except socket.timeout:
                raise ConnectionError("The server sent nothing for %g s." % self._options.server_silence) from None
            if not data:
                raise ConnectionError("The server closed the connection.")
            self._frames.feed(data)

    @property
    def is_open(self):
        return not self._closed

    def close(self):
        """Closes the socket; a thread waiting in ``read`` wakes up with an error."""
        self._closed = True
        try:
            self._transport.sock.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass  # not connected any more: nothing to shut down
        self._transport.sock.close()
