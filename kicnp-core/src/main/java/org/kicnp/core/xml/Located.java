package org.kicnp.core.xml;

import java.util.List;

/**
 * A simple element as read: its raw text, its ITEM-like children (themselves simple elements), where its start tag
 * is and where its text begins (for pointing into a condition). Empty text or {@code NULL} means "absent", unless
 * the text was given in CDATA ({@code literal}): {@code <![CDATA[]]>} is the empty string, not "absent".
 */
record Located(String text, List<Located> items, int line, int column, int textLine, int textColumn, boolean literal) {

    /** The text without surrounding white space. */
    String stripped() {
        return text.strip();
    }

    /** Whether the element says nothing: empty, white space or {@code NULL} not given in CDATA, and no items. */
    boolean absent() {
        return !literal && items.isEmpty() && isNull(text);
    }

    SourceLocation at(String source) {
        return new SourceLocation(source, line, column);
    }

    static boolean isNull(String text) {
        int len = text.length();
        if (len == 0) {
            return true;
        }
        if (!Character.isWhitespace(text.charAt(0)) && !Character.isWhitespace(text.charAt(len - 1))) {
            return len == 4 && text.equalsIgnoreCase("NULL");
        }
        String t = text.strip();
        return t.isEmpty() || t.equalsIgnoreCase("NULL");
    }
}
