#!/usr/bin/env python3
"""A K-ICNP robot agent in Python, with the standard library only: proof that docs/protocol.md is enough.

Usage: python_agent.py PORT NAME TOKEN [HOST [TRUSTED_CERT.pem]]
Connects to HOST:PORT (default 127.0.0.1), authenticates, registers, reports a sensor signal, carries out ONE command
(started, progress, ended) and exits 0. With TRUSTED_CERT.pem it speaks TLS and trusts exactly that certificate (the
server's, as `keytool -exportcert -rfc` writes it: a server's `kicnp serve --listen` address, docs/deployment.md). If the 'jsonschema' package is installed, every message sent and
received is checked against docs/protocol/schemas/TYPE.json, and any mismatch exits with status 3.
"""
import json
import pathlib
import socket
import ssl
import struct
import sys

SCHEMAS = pathlib.Path(__file__).resolve().parent.parent / "protocol" / "schemas"
try:
    import jsonschema
except ImportError:  # validation is a bonus, not a requirement of the protocol
    jsonschema = None
checked = 0


def validate(message):
    global checked
    if jsonschema is None:
        return
    schema = json.loads((SCHEMAS / (message["type"] + ".json")).read_text())
    try:
        jsonschema.validate(message, schema)
    except jsonschema.ValidationError as e:
        print("schema violation in %s: %s" % (message["type"], e.message), file=sys.stderr)
        sys.exit(3)
    checked += 1


def send(sock, message):
    message = {"v": 1, **message}
    validate(message)
    payload = json.dumps(message).encode("utf-8")
    sock.sendall(struct.pack(">I", len(payload)) + payload)


def receive(sock):
    header = read_exactly(sock, 4)
    (length,) = struct.unpack(">I", header)
    message = json.loads(read_exactly(sock, length).decode("utf-8"))
    validate(message)
    return message


def read_exactly(sock, n):
    data = b""
    while len(data) < n:
        chunk = sock.recv(n - len(data))
        if not chunk:
            raise ConnectionError("the gateway closed the connection")
        data += chunk
    return data


def next_of(sock, kind):
    while True:  # heartbeats may come at any time
        message = receive(sock)
        if message["type"] == kind:
            return message
        if message["type"] == "error":
            raise RuntimeError("gateway error %s: %s" % (message["code"], message["message"]))


def connect(host, port, trusted):
    """A plain TCP connection, or TLS checking the server against the one certificate trusted (and its name)."""
    sock = socket.create_connection((host, port), timeout=20)
    if trusted is None:
        return sock
    context = ssl.create_default_context(cafile=trusted)
    return context.wrap_socket(sock, server_hostname=host)


def main():
    port, name, token = int(sys.argv[1]), sys.argv[2], sys.argv[3]
    host = sys.argv[4] if len(sys.argv) > 4 else "127.0.0.1"
    trusted = sys.argv[5] if len(sys.argv) > 5 else None
    with connect(host, port, trusted) as sock:
        send(sock, {"type": "hello", "id": "1", "agent": name, "kind": "robot", "token": token})
        if not next_of(sock, "auth_result")["accepted"]:
            sys.exit(2)
        send(sock, {"type": "register", "id": "2", "capabilities": []})
        next_of(sock, "ack")
        # A battery reading is good for a minute: the server retracts it if no newer one comes by then (ttlMs).
        send(sock, {"type": "sensor", "source": name, "sensor": "battery", "values": [0.87, {"ref": "agent_" + name}],
                    "ttlMs": 60000})
        print("registered", flush=True)
        command = next_of(sock, "command")
        feedback = {"type": "feedback", "id": command["id"], "robot": name}
        send(sock, {**feedback, "stage": "started", "detail": ""})
        send(sock, {**feedback, "stage": "progress", "progress": 0.5, "detail": "halfway"})
        send(sock, {**feedback, "stage": "ended", "detail": "did " + command["action"] + " in Python"})
        send(sock, {"type": "query", "id": "3", "ofClass": "SensorSignal"})
        frames = next_of(sock, "frames")["frames"]
        print("done; %d signal frame(s); %d message(s) checked against the schemas" % (len(frames), checked),
              flush=True)


if __name__ == "__main__":
    main()
