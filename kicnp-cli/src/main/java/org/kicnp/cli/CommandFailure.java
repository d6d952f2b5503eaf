package org.kicnp.cli;

import java.io.PrintWriter;
import java.io.UncheckedIOException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import picocli.CommandLine;
import picocli.CommandLine.IExecutionExceptionHandler;
import picocli.CommandLine.ParseResult;

/**
 * What a verb that fails with an exception prints: {@code kicnp VERB: sentence} on stderr and exit code 1. The
 * platform's exceptions already say what went wrong and where (a knowledge file's errors with their lines, a port
 * in use), so a person reads that sentence, not a Java stack trace; the trace goes to the debug log.
 */
final class CommandFailure implements IExecutionExceptionHandler {
    private static final Logger LOG = LoggerFactory.getLogger(CommandFailure.class);

    @Override public int handleExecutionException(Exception e, CommandLine command, ParseResult parsed) {
        LOG.debug("kicnp {} failed", command.getCommandName(), e);
        PrintWriter err = command.getErr();
        err.println(command.getCommandSpec().qualifiedName() + ": " + sentence(e));
        err.flush();
        return 1;
    }

    private static String sentence(Exception e) {
        String message = e.getMessage() == null ? "" : e.getMessage().strip();
        // The platform's own exceptions, and the JDK ones it throws with a sentence, speak for themselves; a terse
        // JDK message ("Port out of range:70000") keeps the exception's name for context.
        boolean ours = e.getClass().getName().startsWith("org.kicnp.") || e instanceof UncheckedIOException
                || message.endsWith(".");
        if (ours && !message.isEmpty()) {
            return message;
        }
        return e.getClass().getSimpleName() + (message.isEmpty() ? "" : ": " + message);
    }
}
