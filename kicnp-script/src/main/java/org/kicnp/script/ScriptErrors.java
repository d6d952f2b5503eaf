package org.kicnp.script;

import java.time.Duration;
import java.util.OptionalInt;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.graalvm.polyglot.PolyglotException;
import org.graalvm.polyglot.SourceSection;

/** Translates what GraalJS throws into the runtime's exceptions, each naming the script's frame and slot. */
final class ScriptErrors {

    private ScriptErrors() {
    }

    /** The exception for a source that does not parse; lines and columns refer to the text as written. */
    static ScriptSyntaxException syntax(ScriptId id, String text, PolyglotException e) {
        SourceSection at = e.getSourceLocation();
        int lines = Math.max(1, (int) text.lines().count());
        int line = at == null ? 1 : Math.max(1, at.getStartLine());
        int column = at == null ? 1 : Math.max(1, at.getStartColumn());
        if (line > lines) {
            line = lines;
            column = text.lines().reduce((a, b) -> b).map(String::length).orElse(0) + 1;
        }
        return new ScriptSyntaxException(id, line, column, parserMessage(id, e));
    }

    /** The exception for a failed run. {@code stopped} says whether the watchdog stopped it. */
    static ScriptException run(ScriptId id, PolyglotException e, boolean stopped, ScriptConfig config) {
        if (stopped) {
            return new ScriptTimeoutException(id, ScriptTimeoutException.Limit.TIME, millis(config.timeLimit()), e);
        }
        if (e.isResourceExhausted() || isStatementLimit(e)) {
            return new ScriptTimeoutException(id, ScriptTimeoutException.Limit.STATEMENTS,
                    config.statementLimit() + " statements", e);
        }
        if (e.isHostException()) {
            Throwable host = e.asHostException();
            return new ScriptFailedException(id, host.getClass().getSimpleName() + ": " + host.getMessage(), line(id, e), host);
        }
        if (e.isExit()) {
            return new ScriptFailedException(id, "the script tried to exit the runtime (exit code " + e.getExitStatus() + ")",
                    OptionalInt.empty(), e);
        }
        if (e.isCancelled()) {
            return new ScriptFailedException(id, "the run was cancelled because the script runtime is closing",
                    OptionalInt.empty(), e);
        }
        return new ScriptFailedException(id, String.valueOf(e.getMessage()), line(id, e), e);
    }

    /** The exception for a run that failed outside JavaScript, for example while converting its result. */
    static ScriptException conversion(ScriptId id, RuntimeException e) {
        return new ScriptFailedException(id, e.getMessage(), OptionalInt.empty(), e);
    }

    /** Whether the context must be thrown away after this exception rather than reused. */
    static boolean poisons(PolyglotException e) {
        return e.isCancelled() || e.isInterrupted() || e.isResourceExhausted() || e.isInternalError() || e.isExit();
    }

    private static boolean isStatementLimit(PolyglotException e) {
        return e.isCancelled() && String.valueOf(e.getMessage()).contains("Statement count limit");
    }

    private static OptionalInt line(ScriptId id, PolyglotException e) {
        for (PolyglotException.StackFrame frame : e.getPolyglotStackTrace()) {
            SourceSection at = frame.getSourceLocation();
            if (frame.isGuestFrame() && at != null && id.sourceName().equals(at.getSource().getName())) {
                return OptionalInt.of(at.getStartLine());
            }
        }
        return OptionalInt.empty();
    }

    /** The parser's message without the {@code SyntaxError: name:line:column} prefix and the caret diagram. */
    private static String parserMessage(ScriptId id, PolyglotException e) {
        String message = String.valueOf(e.getMessage());
        int newline = message.indexOf('\n');
        String first = newline < 0 ? message : message.substring(0, newline);
        Matcher prefix = Pattern.compile("^(?:SyntaxError:\\s*)?" + Pattern.quote(id.sourceName()) + ":\\d+:\\d+\\s*")
                .matcher(first);
        return prefix.lookingAt() ? first.substring(prefix.end()).strip() : first.strip();
    }

    private static String millis(Duration d) {
        return d.toMillis() + " ms";
    }
}
