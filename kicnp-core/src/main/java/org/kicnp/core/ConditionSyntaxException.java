package org.kicnp.core;

/** A condition's text does not follow the condition syntax. {@link #column()} is 1-based within the text. */
public final class ConditionSyntaxException extends KnowledgeException {
    private final int column;

    ConditionSyntaxException(String expected, int column, String text) {
        super("Condition '" + text + "' is not valid at character " + column + ": expected " + expected + ".");
        this.column = column;
    }

    /** The 1-based position in the condition text where parsing stopped. */
    public int column() {
        return column;
    }
}
