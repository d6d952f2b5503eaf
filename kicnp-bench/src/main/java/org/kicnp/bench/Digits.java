package org.kicnp.bench;

import io.netty.buffer.ByteBuf;

/** Fixed-width decimal numbers written into and read out of message bytes in place, without allocation. */
final class Digits {
    private Digits() {
    }

    /** Writes {@code value} (0 or more) as exactly {@code width} ASCII digits at {@code index}, zero-padded. */
    static void put(ByteBuf buf, int index, long value, int width) {
        long v = value;
        for (int i = index + width - 1; i >= index; i--) {
            buf.setByte(i, (int) ('0' + v % 10));
            v /= 10;
        }
    }

    /** Reads {@code width} ASCII digits at {@code index}; -1 if a byte there is not a digit. */
    static long get(ByteBuf buf, int index, int width) {
        long v = 0;
        for (int i = index; i < index + width; i++) {
            int d = buf.getByte(i) - '0';
            if (d < 0 || d > 9) {
                return -1;
            }
            v = v * 10 + d;
        }
        return v;
    }
}
