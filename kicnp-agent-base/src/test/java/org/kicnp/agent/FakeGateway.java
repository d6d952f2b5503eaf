package org.kicnp.agent;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;
import org.kicnp.protocol.Framing;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.MessageCodec;

/**
 * A scripted server on loopback for the SDK's tests: the n-th connection runs the n-th script on a virtual thread,
 * then is closed; connections past the last script are closed at once. The gateway itself is tested elsewhere.
 */
final class FakeGateway implements AutoCloseable {
    private static final MessageCodec CODEC = new MessageCodec();

    /** What the server does with one connection. */
    @FunctionalInterface
    interface Script {
        void run(Peer peer) throws Exception;
    }

    /** One accepted connection, read and written in frames. */
    static final class Peer {
        private final Socket socket;
        private final DataInputStream in;
        private final DataOutputStream out;

        private Peer(Socket socket) throws IOException {
            this.socket = socket;
            this.in = new DataInputStream(socket.getInputStream());
            this.out = new DataOutputStream(socket.getOutputStream());
        }

        Message read() throws IOException {
            return CODEC.decode(Framing.read(in, Framing.DEFAULT_MAX_FRAME_BYTES));
        }

        /** The next message that is not a heartbeat. */
        Message readSkippingHeartbeats() throws IOException {
            Message m = read();
            while (m instanceof Message.Heartbeat) {
                m = read();
            }
            return m;
        }

        void send(Message m) throws IOException {
            Framing.write(out, CODEC.encode(m));
        }

        /** Accepts the agent's hello. */
        void authenticate() throws IOException {
            Message.Hello hello = (Message.Hello) readSkippingHeartbeats();
            send(new Message.AuthResult(hello.id(), true, "fake", Optional.empty()));
        }

        /** Accepts the agent's hello and its register. */
        void register() throws IOException {
            authenticate();
            Message.Register reg = (Message.Register) readSkippingHeartbeats();
            send(new Message.Ack(reg.id()));
        }

        /**
         * Reads the length prefix of the next frame of at least {@code bytes} bytes (smaller ones, heartbeats, are
         * dropped) and leaves that frame unread, as a server refusing it for its length does.
         */
        int readLengthOfAFrameOfAtLeast(int bytes) throws IOException {
            while (true) {
                int length = in.readInt();
                if (length >= bytes) {
                    return length;
                }
                in.skipNBytes(length);
            }
        }

        /** Ends what this side sends: the agent reads to the end of the stream; the connection stays open to it. */
        void shutdownOutput() throws IOException {
            socket.shutdownOutput();
        }

        /** Reads (and drops) everything until the agent closes the connection. */
        void drain() {
            try {
                while (true) {
                    read();
                }
            } catch (IOException closed) {
                // the agent is gone
            }
        }
    }

    private final ServerSocket server;
    private final AtomicInteger connections = new AtomicInteger();

    FakeGateway(Script... scripts) throws IOException {
        server = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
        List<Script> each = List.of(scripts);
        Thread.ofVirtual().start(() -> {
            try {
                while (true) {
                    Socket s = server.accept();
                    int n = connections.getAndIncrement();
                    if (n >= each.size()) {
                        s.close();
                        continue;
                    }
                    Thread.ofVirtual().start(() -> {
                        try (s) {
                            each.get(n).run(new Peer(s));
                        } catch (Exception ignored) {
                            // the test ends by closing the agent or the server
                        }
                    });
                }
            } catch (IOException closed) {
                // the test is over
            }
        });
    }

    int port() {
        return server.getLocalPort();
    }

    /** How many connections were accepted so far. */
    int connections() {
        return connections.get();
    }

    @Override public void close() throws IOException {
        server.close();
    }
}
