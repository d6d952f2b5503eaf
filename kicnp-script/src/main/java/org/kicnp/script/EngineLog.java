package org.kicnp.script;

import java.text.MessageFormat;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Where the script engine's own diagnostics go (GraalJS's and Truffle's warnings, such as an option it ignores): the
 * log, under {@code org.kicnp.script.engine}, at the level the engine gave. Without it they are written to the
 * engine's error stream, which is the scripts' ({@link ScriptOutput}), and would read as a behavior script's error
 * output, preceded by Truffle's advice on redirecting its log.
 */
final class EngineLog extends Handler {
    private static final Logger LOG = LoggerFactory.getLogger("org.kicnp.script.engine");

    @Override public void publish(LogRecord record) {
        if (record == null) {
            return;
        }
        String message = record.getMessage();
        if (message != null && record.getParameters() != null && record.getParameters().length > 0) {
            message = MessageFormat.format(message, record.getParameters());
        }
        int level = record.getLevel().intValue();
        if (level >= Level.SEVERE.intValue()) {
            LOG.error("[{}] {}", record.getLoggerName(), message, record.getThrown());
        } else if (level >= Level.WARNING.intValue()) {
            LOG.warn("[{}] {}", record.getLoggerName(), message, record.getThrown());
        } else if (level >= Level.INFO.intValue()) {
            LOG.info("[{}] {}", record.getLoggerName(), message, record.getThrown());
        } else {
            LOG.debug("[{}] {}", record.getLoggerName(), message, record.getThrown());
        }
    }

    @Override public void flush() {
    }

    @Override public void close() {
    }
}
