package org.kicnp.script;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Where {@code console.log} and {@code print} go: line by line into the log, never to the process's standard
 * streams. Lines are buffered per thread, so concurrent scripts do not mix their output.
 */
final class ScriptOutput extends OutputStream {
    private static final Logger LOG = LoggerFactory.getLogger("org.kicnp.script.console");
    private static final int MAX_LINE = 8192;

    private final boolean error;
    private final ThreadLocal<ByteArrayOutputStream> line = ThreadLocal.withInitial(ByteArrayOutputStream::new);

    ScriptOutput(boolean error) {
        this.error = error;
    }

    @Override public void write(int b) {
        ByteArrayOutputStream buffer = line.get();
        if (b == '\n') {
            flushLine(buffer);
        } else if (buffer.size() < MAX_LINE) {
            buffer.write(b);
        }
    }

    @Override public void flush() {
        ByteArrayOutputStream buffer = line.get();
        if (buffer.size() > 0) {
            flushLine(buffer);
        }
    }

    private void flushLine(ByteArrayOutputStream buffer) {
        String text = buffer.toString(StandardCharsets.UTF_8);
        buffer.reset();
        if (error) {
            LOG.warn("Script error output: {}", text);
        } else {
            LOG.info("Script output: {}", text);
        }
    }
}
