package org.kicnp.script;

/**
 * A script does not parse. Carries the 1-based line and column inside the slot's text and the parser's own
 * message, so an editor can point at the mistake before the script is saved.
 */
public final class ScriptSyntaxException extends ScriptException {
    private final int line;
    private final int column;
    private final String parserMessage;

    public ScriptSyntaxException(ScriptId id, int line, int column, String parserMessage) {
        super(id, id.describe() + " has a syntax error at line " + line + ", column " + column + ": " + parserMessage);
        this.line = line;
        this.column = column;
        this.parserMessage = parserMessage;
    }

    /** The 1-based line of the error within the script text. */
    public int line() {
        return line;
    }

    /** The 1-based column of the error within its line. */
    public int column() {
        return column;
    }

    /** What the JavaScript parser said, without the location prefix. */
    public String parserMessage() {
        return parserMessage;
    }
}
