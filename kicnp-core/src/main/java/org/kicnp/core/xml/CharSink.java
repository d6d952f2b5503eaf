package org.kicnp.core.xml;

import java.io.IOException;
import java.io.Writer;

/**
 * An unsynchronised character buffer in front of a {@link Writer}: the XML writer makes millions of tiny writes, and
 * copying them into one array before handing the writer 64 K characters at a time is several times faster than
 * {@link java.io.BufferedWriter}, whose writes take a lock.
 */
final class CharSink {
    private final Writer out;
    private final char[] buf = new char[1 << 16];
    private int pos;

    CharSink(Writer out) {
        this.out = out;
    }

    void write(String s) throws IOException {
        int len = s.length();
        if (len > buf.length - pos) {
            flushBuffer();
            if (len > buf.length) {
                out.write(s);
                return;
            }
        }
        s.getChars(0, len, buf, pos);
        pos += len;
    }

    void write(char c) throws IOException {
        if (pos == buf.length) {
            flushBuffer();
        }
        buf[pos++] = c;
    }

    /** Hands everything buffered to the writer and flushes it. */
    void flush() throws IOException {
        flushBuffer();
        out.flush();
    }

    private void flushBuffer() throws IOException {
        if (pos > 0) {
            out.write(buf, 0, pos);
            pos = 0;
        }
    }
}
