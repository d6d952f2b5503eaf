package org.kicnp.agent;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.concurrent.locks.ReentrantLock;
import org.kicnp.protocol.ErrorCode;
import org.kicnp.protocol.Message;
import org.kicnp.protocol.MessageCodec;
import org.kicnp.protocol.MessageType;
import org.kicnp.protocol.Framing;

/**
 * One TCP connection to a gateway: framed, blocking reads and writes of {@link Message}s. Writes are serialised by
 * a lock (not {@code synchronized}, so a virtual thread waiting for it does not pin its carrier).
 */
final class Connection implements AutoCloseable {
    private final Socket socket;
    private final DataInputStream in;
    private final DataOutputStream out;
    private final MessageCodec codec;
    private final int maxFrameBytes;
    private final ReentrantLock writeLock = new ReentrantLock();

    private Connection(Socket socket, MessageCodec codec, int maxFrameBytes) throws IOException {
        this.socket = socket;
        this.in = new DataInputStream(new BufferedInputStream(socket.getInputStream()));
        this.out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream()));
        this.codec = codec;
        this.maxFrameBytes = maxFrameBytes;
    }

    static Connection open(AgentOptions o, MessageCodec codec) throws IOException {
        Socket s = o.socketFactory().createSocket();
        try {
            s.setTcpNoDelay(true);
            s.connect(new InetSocketAddress(o.host(), o.port()), (int) o.requestTimeout().toMillis());
            s.setSoTimeout((int) o.serverSilence().toMillis());
            return new Connection(s, codec, o.maxFrameBytes());
        } catch (IOException | RuntimeException e) {
            s.close();
            throw e;
        }
    }

    /**
     * Writes one message.
     *
     * @throws RequestRefusedException with {@code frame_too_large}, sending nothing, when the message is longer than
     *     one frame may be ({@link AgentOptions#maxFrameBytes}, the server's default limit too): a server cuts a long
     *     frame off while it is still being written, and the sender would only hear "connection reset"
     */
    void send(Message m) throws IOException {
        byte[] payload = codec.encode(m);
        if (payload.length > maxFrameBytes) {
            throw new RequestRefusedException(ErrorCode.FRAME_TOO_LARGE, "The " + MessageType.of(m).wireName()
                    + " message is " + payload.length + " bytes, more than one message may carry (" + maxFrameBytes
                    + " bytes, AgentOptions.maxFrameBytes); nothing was sent: send less, such as a smaller subtree.");
        }
        writeLock.lock();
        try {
            Framing.write(out, payload);
        } finally {
            writeLock.unlock();
        }
    }

    /** Blocks for the next message; a {@link org.kicnp.protocol.ProtocolException} if the server sent garbage. */
    Message read() throws IOException {
        return codec.decode(Framing.read(in, maxFrameBytes));
    }

    boolean isOpen() {
        return !socket.isClosed();
    }

    @Override public void close() {
        try {
            socket.close();
        } catch (IOException ignored) {
            // Closing is best effort; the socket is unusable either way.
        }
    }
}
