package org.kicnp.protocol;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;

/**
 * The frame layout: a 4-byte big-endian length, then that many bytes of payload. Blocking helpers for clients
 * that use plain sockets (the agent SDK, tests, agents in other JVM languages); the gateway uses Netty's
 * {@code LengthFieldBasedFrameDecoder} with the same constants.
 */
public final class Framing {
    /** Bytes in the length prefix. */
    public static final int LENGTH_BYTES = 4;
    /** The default largest payload: 1 MiB. */
    public static final int DEFAULT_MAX_FRAME_BYTES = 1 << 20;

    private Framing() {
    }

    /**
     * Reads one frame's payload.
     *
     * @throws ProtocolException with {@link ErrorCode#FRAME_TOO_LARGE} when the length exceeds {@code maxBytes}
     * @throws java.io.EOFException when the stream ends
     */
    public static byte[] read(DataInputStream in, int maxBytes) throws IOException {
        int length = in.readInt();
        if (length < 0 || length > maxBytes) {
            throw new ProtocolException(ErrorCode.FRAME_TOO_LARGE, "A frame of " + Integer.toUnsignedString(length)
                    + " bytes exceeds the limit of " + maxBytes + " bytes.");
        }
        byte[] payload = new byte[length];
        in.readFully(payload);
        return payload;
    }

    /** Writes one frame and flushes it. Callers serialise writers themselves. */
    public static void write(DataOutputStream out, byte[] payload) throws IOException {
        out.writeInt(payload.length);
        out.write(payload);
        out.flush();
    }
}
