package org.kicnp.core;

/** A condition's text does not follow the condition syntax. {@link #column()} is 1-based within the text. */
public final class ConditionSyntaxException extends KnowledgeException {
    private final int column;

    ConditionSyntaxException(String expected, int column, String text) {
        this(column, text, "expected " + expected + ".");
    }

    private ConditionSyntaxException(int column, String text, String reason) {
        super("Condition '" + text + "' is not valid at character " + column + ": " + reason);
        this.column = column;
    }

    /** For a part that parsed but is wrong in itself, such as a regular expression: {@code reason} is a sentence. */
    static ConditionSyntaxException because(String reason, int column, String text) {
        return new ConditionSyntaxException(column, text, reason);
    }

    /** The 1-based position in the condition text where parsing stopped. */
    public int column() {
        return column;
    }
}
