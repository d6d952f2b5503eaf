package org.kicnp.core.xml;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;

/**
 * Finds the first byte of a file that is not UTF-8, with its line and column. The XML parser decodes ahead of the
 * element it is reading, so when it meets such a byte it knows neither: a Latin-1 'é' in a small file was reported
 * at line 1, column 1. Only called once a parse has failed that way, so loading pays nothing for it.
 */
final class Utf8Check {
    private Utf8Check() {
    }

    /** The error at the first malformed byte, or empty when the file decodes (or cannot be read again). */
    static Optional<LoadError> firstMalformed(Path file, String source) {
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.allocate(1 << 16);
        CharBuffer out = CharBuffer.allocate(1 << 16);
        int line = 1;
        int column = 1;
        boolean afterCr = false;
        try (InputStream stream = Files.newInputStream(file)) {
            boolean end = false;
            while (true) {
                int n = end ? -1 : stream.read(in.array(), in.position(), in.remaining());
                end = n < 0;
                if (n > 0) {
                    in.position(in.position() + n);
                }
                in.flip();
                CoderResult result = decoder.decode(in, out, end);
                out.flip();
                while (out.hasRemaining()) {
                    char c = out.get();
                    if (c == '\n' && afterCr) {
                        afterCr = false;
                    } else if (c == '\n' || c == '\r') {
                        line++;
                        column = 1;
                        afterCr = c == '\r';
                    } else {
                        column++;
                        afterCr = false;
                    }
                }
                out.clear();
                if (result.isError()) {
                    int b = in.get(in.position()) & 0xFF;
                    return Optional.of(new LoadError(source, line, column, String.format(Locale.ROOT,
                            "The file is not valid UTF-8: byte 0x%02X here does not make a UTF-8 character; save the "
                                    + "file as UTF-8, or name its encoding in the XML declaration "
                                    + "(<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>).", b)));
                }
                in.compact();
                if (end && result.isUnderflow()) {
                    return Optional.empty();
                }
            }
        } catch (IOException e) {
            return Optional.empty();
        }
    }
}
