"""The wire format of docs/protocol.md: 4-byte big-endian length, then one JSON object with ``"v": 1``.

Messages from the server are checked here, once, at the edge: a frame that is too long, not JSON, of another version,
of an unknown type or without a required member is a :class:`ProtocolError` naming what was wrong, and the rest of
the SDK can read the members it needs without checking again.
"""
import json
import struct

from .errors import ProtocolError, RequestRefusedError

VERSION = 1
DEFAULT_MAX_FRAME_BYTES = 1024 * 1024
# The most characters the server takes in a name, an action, an id, a relay's subject or a class name a request asks
# about (org.kicnp.protocol.Message.MAX_NAME_LENGTH); a longer one is bad_message, and the server closes the connection.
MAX_NAME_LENGTH = 256
_HEADER = struct.Struct(">I")

# The required members of each message a server may send an agent (docs/protocol/schemas/TYPE.json, less v and type).
_REQUIRED = {
    "auth_result": ("id", "accepted", "server"),
    "ack": ("id",),
    "heartbeat": ("time",),
    "relay": ("id", "from", "subject", "body"),
    "command": ("id", "robot", "action", "args"),
    "cancel": ("id", "robot", "command", "reason"),
    "feedback": ("id", "robot", "stage", "detail"),
    "frames": ("id", "frames"),
    "answer": ("id",),
    "changed": ("ofClass", "change", "name"),
    "proofs": ("id", "proofs"),
    "explained": ("id", "reason"),
    "not_fired": ("id", "frame", "summary", "slots", "bindings", "truncated"),
    "error": ("code", "message"),
}


def encode(message, max_frame_bytes=DEFAULT_MAX_FRAME_BYTES):
    """One frame for ``message`` (a dict with ``type``), the version added.

    A message longer than ``max_frame_bytes`` is refused before anything is sent, with the code the server would
    give (``frame_too_large``): the server cuts a long frame off while it is still being written, and the sender
    would hear only "connection reset".
    """
    payload = json.dumps({"v": VERSION, **message}, ensure_ascii=False, allow_nan=False,
                         separators=(",", ":")).encode("utf-8")
    if len(payload) > max_frame_bytes:
        raise RequestRefusedError("frame_too_large", "The %s message is %d bytes, more than one message may carry "
                                  "(%d bytes, max_frame_bytes); nothing was sent: send less."
                                  % (message["type"], len(payload), max_frame_bytes))
    return _HEADER.pack(len(payload)) + payload


def length(text):
    """The length of ``text`` as the server (Java) counts it, in UTF-16 units: a character beyond the basic plane
    counts two."""
    return len(text.encode("utf-16-le", "surrogatepass")) // 2


def check_lengths(call, **arguments):
    """Refuses, before anything is sent, an argument of ``call`` the server would refuse as longer than
    :data:`MAX_NAME_LENGTH` (counted by :func:`length`): it would close the connection over it, dropping every
    request in flight with it. Arguments that are not text are left to the checks that follow.
    """
    for argument, value in arguments.items():
        if isinstance(value, str) and length(value) > MAX_NAME_LENGTH:
            raise ValueError("The argument '%s' of %s is %d characters long; the server allows at most %d, so nothing "
                             "was sent." % (argument, call, length(value), MAX_NAME_LENGTH))


def decode(payload):
    """The message in one frame's payload, checked against the protocol; :class:`ProtocolError` if it is not one."""
    try:
        message = json.loads(payload.decode("utf-8"))
    except (UnicodeDecodeError, ValueError) as e:
        raise ProtocolError("The server sent a frame that is not UTF-8 JSON (%s)." % e) from None
    if not isinstance(message, dict):
        raise ProtocolError("The server sent a frame that is not a JSON object: %.80s." % payload.decode("utf-8"))
    if message.get("v") != VERSION:
        raise ProtocolError("The server speaks protocol version %r, not %d." % (message.get("v"), VERSION))
    kind = message.get("type")
    if kind not in _REQUIRED:
        raise ProtocolError("The server sent a message of type %r, which an agent does not expect." % (kind,))
    for member in _REQUIRED[kind]:
        if message.get(member) is None:
            raise ProtocolError("The server's %s message lacks the member '%s'." % (kind, member))
    return message


class FrameBuffer:
    """Collects received bytes and cuts them into frames; a length over ``max_frame_bytes`` is refused unread."""

    def __init__(self, max_frame_bytes=DEFAULT_MAX_FRAME_BYTES):
        self._max = max_frame_bytes
        self._buffer = bytearray()

    def feed(self, data):
        self._buffer += data

    def next_frame(self):
        """The next whole frame's payload, or None until more bytes have come."""
        if len(self._buffer) < _HEADER.size:
            return None
        (length,) = _HEADER.unpack_from(self._buffer)
        if length == 0:
            raise ProtocolError("The server sent an empty frame.")
        if length > self._max:
            raise ProtocolError("The server sent a frame of %d bytes, more than the %d bytes this agent accepts "
                                "(max_frame_bytes)." % (length, self._max))
        end = _HEADER.size + length
        if len(self._buffer) < end:
            return None
        payload = bytes(self._buffer[_HEADER.size:end])
        del self._buffer[:end]
        return payload
