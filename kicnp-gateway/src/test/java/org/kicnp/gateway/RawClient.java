package org.kicnp.gateway;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.net.Socket;
import java.net.SocketException;
import java.util.ArrayList;
import java.util.List;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.Message;

/** A bare socket speaking (or breaking) the protocol, to test what the SDK would never send. */
final class RawClient implements AutoCloseable {
    final Socket socket;
    private final DataInputStream in;
    private final DataOutputStream out;

    RawClient(int port) throws IOException {
        this(port, 0);
    }

    RawClient(int port, int receiveBuffer) throws IOException {
        socket = new Socket();
        if (receiveBuffer > 0) {
            socket.setReceiveBufferSize(receiveBuffer);
        }
        socket.connect(new java.net.InetSocketAddress("127.0.0.1", port), 5000);
        socket.setSoTimeout(10_000);
        in = new DataInputStream(socket.getInputStream());
        out = new DataOutputStream(socket.getOutputStream());
    }

    void send(Message m) throws IOException {
        sendPayload(Wire.CODEC.encode(m));
    }

    void sendPayload(byte[] payload) throws IOException {
        Framing.write(out, payload);
    }

    void sendBytes(byte[] raw) throws IOException {
        out.write(raw);
        out.flush();
    }

    Message read() throws IOException {
        return Wire.CODEC.decode(Framing.read(in, Framing.DEFAULT_MAX_FRAME_BYTES));
    }

    /** Reads messages until the server closes the connection. */
    List<Message> readUntilClosed() throws IOException {
        List<Message> got = new ArrayList<>();
        try {
            while (true) {
                got.add(read());
            }
        } catch (EOFException | SocketException closed) {
            return got;
        }
    }

    @Override public void close() throws IOException {
        socket.close();
    }
}
