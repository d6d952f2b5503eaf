"""The wire format and values, without a gateway: framing, the checks on what a server sends, slot values."""
import json
import math
import struct
import unittest
from unittest import mock

from kicnp_agent import AgentOptions, ProtocolError, Ref, RequestRefusedError
from kicnp_agent import wire
from kicnp_agent.connection import Connection
from kicnp_agent.messages import value_from_json, value_to_json
from kicnp_agent.wire import DEFAULT_MAX_FRAME_BYTES, FrameBuffer, decode, encode

CHUNK = 65536  # what one receive of the stand-in transport returns at most, as one recv of the real one


def frame(message):
    payload = json.dumps(message).encode("utf-8")
    return struct.pack(">I", len(payload)) + payload


def heartbeat(size):
    """A heartbeat frame whose payload is exactly ``size`` bytes, padded with a member the agent ignores."""
    bare = len(json.dumps({"v": 1, "type": "heartbeat", "time": 5, "pad": ""}).encode("utf-8"))
    return frame({"v": 1, "type": "heartbeat", "time": 5, "pad": "x" * (size - bare)})


class ChunkedTransport:
    """Stands in for the socket: each receive returns the next of the chunks given, and is counted."""

    def __init__(self, chunks):
        self.chunks = list(chunks)
        self.receives = 0
        self.sock = None

    def receive(self):
        self.receives += 1
        return self.chunks.pop(0) if self.chunks else b""


class CountingFrameBuffer(FrameBuffer):
    """A FrameBuffer that counts the bytes it holds (fed, less the frames it has cut) and the most it has held."""

    made = []

    def __init__(self, max_frame_bytes):
        super().__init__(max_frame_bytes)
        self.held = self.most = 0
        CountingFrameBuffer.made.append(self)

    def feed(self, data):
        super().feed(data)
        self.held += len(data)
        self.most = max(self.most, self.held)

    def next_frame(self):
        payload = super().next_frame()
        if payload is not None:
            self.held -= 4 + len(payload)
        return payload


class WireTest(unittest.TestCase):

    def test_encode_writesTheLengthThenCompactJsonWithTheVersion(self):
        data = encode({"type": "ack", "id": "7"})
        self.assertEqual(b'\x00\x00\x00\x1d{"v":1,"type":"ack","id":"7"}', data)
        self.assertEqual(len(data) - 4, struct.unpack(">I", data[:4])[0])

    def test_encode_keepsUnicodeAsUtf8_andCountsBytesNotCharacters(self):
        data = encode({"type": "relay", "body": "Grüße"})
        self.assertEqual(len(data) - 4, struct.unpack(">I", data[:4])[0])
        self.assertIn("Grüße".encode("utf-8"), data)

    def test_encode_refusesAMessageLongerThanAFrame_beforeSendingAnything(self):
        with self.assertRaises(RequestRefusedError) as refused:
            encode({"type": "assert", "id": "1", "frame": "x" * 2000}, max_frame_bytes=1024)
        self.assertEqual("frame_too_large", refused.exception.code)
        self.assertIn("The assert message is 2043 bytes, more than one message may carry (1024 bytes", str(refused.exception))

    def test_frameBuffer_cutsFramesThatArriveInPieces(self):
        stream = frame({"v": 1, "type": "ack", "id": "1"}) + frame({"v": 1, "type": "heartbeat", "time": 5})
        buffer = FrameBuffer()
        frames = []
        for i in range(0, len(stream), 3):
            buffer.feed(stream[i:i + 3])
            payload = buffer.next_frame()
            while payload is not None:
                frames.append(decode(payload))
                payload = buffer.next_frame()
        self.assertEqual([{"v": 1, "type": "ack", "id": "1"}, {"v": 1, "type": "heartbeat", "time": 5}], frames)

    def test_frameBuffer_refusesAnEmptyOrTooLongFrame(self):
        for header, message in ((b"\x00\x00\x00\x00", "The server sent an empty frame."),
                                (b"GET ", "The server sent a frame of 1195725856 bytes, more than the 1048576 bytes "
                                          "this agent accepts (max_frame_bytes).")):
            buffer = FrameBuffer()
            buffer.feed(header)
            with self.assertRaises(ProtocolError) as error:
                buffer.next_frame()
            self.assertEqual(message, str(error.exception))

    def test_read_refusesALengthOverTheMaximum_asSoonAsItsFourBytesArrive_askingForNoneOfThePayload(self):
        header = struct.pack(">I", DEFAULT_MAX_FRAME_BYTES + 1)
        transport = ChunkedTransport([frame({"v": 1, "type": "ack", "id": "1"}) + header[:2],  # the length in two
                                      header[2:] + b'{"v":1,"type":"ack"'] + [b"x" * CHUNK] * 20)  # never to be read
        connection = Connection(transport, AgentOptions("scout", "t"))
        self.assertEqual({"v": 1, "type": "ack", "id": "1"}, connection.read())
        with self.assertRaises(ProtocolError) as error:
            connection.read()
        self.assertEqual("The server sent a frame of 1048577 bytes, more than the 1048576 bytes this agent accepts "
                         "(max_frame_bytes).", str(error.exception))
        self.assertEqual(2, transport.receives)  # the chunk with the length's last two bytes, and nothing after it

    def test_read_holdsAtMostOneMaximumFramePlusOneReceive_andAcceptsAFrameOfExactlyTheMaximum(self):
        largest = DEFAULT_MAX_FRAME_BYTES
        sizes = [largest, 100, largest - 1, largest, 1000, largest]  # maximum frames straddling the chunks
        stream = b"".join(heartbeat(size) for size in sizes)
        tail = struct.pack(">I", largest + 1) + b"x" * (3 * CHUNK)  # a length too long, then payload never to be read
        transport = ChunkedTransport((stream + tail)[i:i + CHUNK] for i in range(0, len(stream + tail), CHUNK))
        receives_up_to_the_bad_length = (len(stream) + 3) // CHUNK + 1  # to the chunk with its last byte
        CountingFrameBuffer.made.clear()
        with mock.patch.object(wire, "FrameBuffer", CountingFrameBuffer):
            connection = Connection(transport, AgentOptions("scout", "t"))
        read = []
        with self.assertRaises(ProtocolError) as error:
            while True:
                read.append(connection.read())
        self.assertIn("a frame of 1048577 bytes, more than the 1048576 bytes", str(error.exception))
        self.assertEqual(sizes, [len(json.dumps(m).encode("utf-8")) for m in read])
        (frames,) = CountingFrameBuffer.made
        self.assertLessEqual(frames.most, 4 + largest + CHUNK)  # one maximum frame, its length, and one receive
        self.assertGreater(frames.most, 4 + largest)  # the stream did make it hold that much
        self.assertEqual(receives_up_to_the_bad_length, transport.receives)

    def test_decode_refusesWhatIsNotAMessageForAnAgent_sayingWhat(self):
        cases = [(b"[1]", "The server sent a frame that is not a JSON object: [1]."),
                 (b'{"v":2,"type":"ack","id":"1"}', "The server speaks protocol version 2, not 1."),
                 (b'{"v":1,"type":"hello","id":"1"}', "The server sent a message of type 'hello', which an agent "
                                                      "does not expect."),
                 (b'{"v":1,"type":"command","id":"c","robot":"r","action":"a"}',
                  "The server's command message lacks the member 'args'.")]
        for payload, message in cases:
            with self.assertRaises(ProtocolError) as error:
                decode(payload)
            self.assertEqual(message, str(error.exception))
        with self.assertRaises(ProtocolError) as error:
            decode(b"{nope")
        self.assertTrue(str(error.exception).startswith("The server sent a frame that is not UTF-8 JSON"))

    def test_values_travelAsTheProtocolTypesThem(self):
        values = ["near", 7, 1.5, True, Ref("userA"), [0.1, Ref("ken")]]
        wire = [value_to_json(v, "value") for v in values]
        self.assertEqual(["near", 7, 1.5, True, {"ref": "userA"}, [0.1, {"ref": "ken"}]], wire)
        self.assertEqual(values, [value_from_json(v) for v in wire])

    def test_floatsJsonHasNoNumberFor_arriveFloatsFromTheirTaggedForm(self):
        received = value_from_json([{"float": "NaN"}, {"float": "Infinity"}, [1.5, {"float": "-Infinity"}]])
        self.assertTrue(math.isnan(received[0]))
        self.assertEqual([float("inf"), [1.5, float("-inf")]], received[1:])
        with self.assertRaises(KeyError):
            value_from_json({"float": "nan"})

    def test_values_refuseNaNInfinityAndOtherTypes_namingTheValue(self):
        with self.assertRaises(ValueError) as error:
            value_to_json([1.0, float("nan")], "Value 1 of sensor 'sonar'")
        self.assertEqual("Value 1 of sensor 'sonar'[1] is nan, which JSON cannot carry; send a finite number.",
                         str(error.exception))
        with self.assertRaises(ValueError):
            value_to_json(float("-inf"), "v")
        with self.assertRaises(TypeError) as error:
            value_to_json({"x": 1}, "Value 2 of sensor 'arm'")
        self.assertIn("Value 2 of sensor 'arm' is a dict", str(error.exception))


if __name__ == "__main__":
    unittest.main()
