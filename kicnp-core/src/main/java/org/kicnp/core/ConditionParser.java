package org.kicnp.core;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Parses the text of a CONDITION element.
 *
 * <pre>
 * condition := "" | "COND_ANY" | "ANY" | ("js:" | "script:") script
 *            | [left] op operand | [left] "between" operand "and" operand
 *            | [left] "in" "(" operand ("," operand)* ")" | [left] "matches" string
 * left      := "." name ("." name)*          a slot of the instance held by this slot
 * op        := "==" | "=" | "!=" | "&lt;" | "&lt;=" | "&gt;" | "&gt;="
 * operand   := string | number | TRUE | FALSE | "@" frame-name | name ("." name)*
 * </pre>
 * A bare name path such as {@code mUser.name} refers to the binding; {@code s.mUser.name}, as scripts write it, is
 * accepted too. {@code @Kitchen} is a constant reference to the frame Kitchen.
 */
public final class ConditionParser {
    private final String text;
    private int pos;

    private ConditionParser(String text) {
        this.text = text;
    }

    /**
     * Parses a condition.
     *
     * @throws ConditionSyntaxException naming the column and what was expected
     */
    public static Condition parse(String text) {
        String t = text.strip();
        String upper = t.toUpperCase(Locale.ROOT);
        if (t.isEmpty() || upper.equals("COND_ANY") || upper.equals("ANY") || upper.equals("NULL")) {
            return Condition.ANY;
        }
        for (String prefix : List.of("js:", "script:")) {
            if (t.regionMatches(true, 0, prefix, 0, prefix.length())) {
                String script = t.substring(prefix.length()).strip();
                if (script.isEmpty()) {
                    throw new ConditionSyntaxException("a script after '" + prefix + "'", prefix.length() + 1, text);
                }
                return new Condition.Script(script);
            }
        }
        return new ConditionParser(t).condition();
    }

    private Condition condition() {
        List<String> left = List.of();
        skipSpace();
        if (peek() == '.') {
            pos++;
            left = names();
        }
        skipSpace();
        Condition c;
        if (word("between")) {
            Operand low = operand();
            if (!word("and")) {
                throw error("'and' after the lower bound");
            }
            c = new Condition.Between(left, low, operand());
        } else if (word("in")) {
            expect('(');
            List<Operand> options = new ArrayList<>();
            do {
                options.add(operand());
                skipSpace();
            } while (accept(','));
            expect(')');
            c = new Condition.OneOf(left, options);
        } else if (word("matches")) {
            skipSpace();
            Operand re = operand();
            if (!(re instanceof Operand.Constant k && k.value() instanceof Value.Str s)) {
                throw error("a quoted regular expression after 'matches'");
            }
            try {
                c = new Condition.Matches(left, s.value());
            } catch (IllegalArgumentException e) {
                throw ConditionSyntaxException.because(e.getMessage(), pos, text);
            }
        } else {
            Condition.Op op = op();
            c = new Condition.Compare(left, op, operand());
        }
        skipSpace();
        if (pos < text.length()) {
            throw error("the end of the condition");
        }
        return c;
    }

    private Condition.Op op() {
        skipSpace();
        String[] symbols = {"==", "!=", "<=", ">=", "<>", "=", "<", ">"};
        for (String sym : symbols) {
            if (text.startsWith(sym, pos)) {
                pos += sym.length();
                return switch (sym) {
                    case "==", "=" -> Condition.Op.EQ;
                    case "!=", "<>" -> Condition.Op.NE;
                    case "<=" -> Condition.Op.LE;
                    case ">=" -> Condition.Op.GE;
                    case "<" -> Condition.Op.LT;
                    default -> Condition.Op.GT;
                };
            }
        }
        throw error("a comparison (==, !=, <, <=, >, >=), 'between', 'in' or 'matches'");
    }

    private Operand operand() {
        skipSpace();
        char c = peek();
        if (c == '"' || c == '\'' || c == '\u201C' || c == '\u2018') {
            return new Operand.Constant(Value.of(string()));
        }
        if (c == '@') {
            pos++;
            return new Operand.Constant(Value.ref(frameName()));
        }
        if (c == '-' || c == '+' || Character.isDigit(c)) {
            return new Operand.Constant(number());
        }
        if (Character.isJavaIdentifierStart(c)) {
            List<String> path = names();
            if (path.size() == 1) {
                String w = path.getFirst().toUpperCase(Locale.ROOT);
                if (w.equals("TRUE") || w.equals("FALSE")) {
                    return new Operand.Constant(Value.of(w.equals("TRUE")));
                }
            }
            if (path.size() > 1 && path.getFirst().equals("s")) {
                path = path.subList(1, path.size());
            }
            return new Operand.Path(path);
        }
        throw error("a value: a quoted string, a number, TRUE, FALSE, @Frame or a slot path");
    }

    private String string() {
        char open = text.charAt(pos++);
        char close = switch (open) {
            case '\u201C' -> '\u201D';
            case '\u2018' -> '\u2019';
            default -> open;
        };
        StringBuilder sb = new StringBuilder();
        while (pos < text.length()) {
            char c = text.charAt(pos++);
            if (c == close) {
                return sb.toString();
            }
            if (c == '\\' && pos < text.length()) {
                c = text.charAt(pos++);
            }
            sb.append(c);
        }
        throw error("a closing quote");
    }

    private Value number() {
        int start = pos;
        if (peek() == '-' || peek() == '+') {
            pos++;
        }
        while (pos < text.length() && (Character.isDigit(peek()) || ".eE+-".indexOf(peek()) >= 0)) {
            pos++;
        }
        String n = text.substring(start, pos);
        boolean whole = n.matches("[-+]?\\d+");
        try {
            Value v = whole ? Value.of(Long.parseLong(n)) : Value.of(Double.parseDouble(n));
            if (v instanceof Value.Real r && Double.isInfinite(r.value())) {
                pos = start;
                throw error("a number up to about 1.8e308 (found '" + n + "')");
            }
            return v;
        } catch (NumberFormatException e) {
            pos = start;
            throw error(whole ? "a whole number from " + Long.MIN_VALUE + " to " + Long.MAX_VALUE
                    + " (found '" + n + "')" : "a number (found '" + n + "')");
        }
    }

    private List<String> names() {
        List<String> names = new ArrayList<>();
        names.add(name());
        while (peek() == '.') {
            pos++;
            names.add(name());
        }
        return names;
    }

    private String name() {
        int start = pos;
        if (pos < text.length() && Character.isJavaIdentifierStart(text.charAt(pos))) {
            pos++;
            while (pos < text.length() && Character.isJavaIdentifierPart(text.charAt(pos))) {
                pos++;
            }
        }
        if (start == pos) {
            throw error("a slot or frame name");
        }
        return Names.canonical(text.substring(start, pos)); // the very String of the slots it names
    }

    /** A frame name after '@': as {@link Names#isFrameName} allows, so with '-' (AIBO-1), unlike a slot name. */
    private String frameName() {
        int start = pos;
        if (pos < text.length() && (Character.isLetter(text.charAt(pos)) || text.charAt(pos) == '_')) {
            pos++;
            while (pos < text.length() && (Character.isLetterOrDigit(text.charAt(pos)) || text.charAt(pos) == '_'
                    || text.charAt(pos) == '-')) {
                pos++;
            }
        }
        if (start == pos) {
            throw error("a frame name after '@'");
        }
        return text.substring(start, pos);
    }

    private boolean word(String w) {
        skipSpace();
        int end = pos + w.length();
        if (text.regionMatches(true, pos, w, 0, w.length())
                && (end == text.length() || !Character.isJavaIdentifierPart(text.charAt(end)))) {
            pos = end;
            return true;
        }
        return false;
    }

    private boolean accept(char c) {
        skipSpace();
        if (peek() == c) {
            pos++;
            return true;
        }
        return false;
    }

    private void expect(char c) {
        if (!accept(c)) {
            throw error("'" + c + "'");
        }
    }

    private char peek() {
        return pos < text.length() ? text.charAt(pos) : '\0';
    }

    private void skipSpace() {
        while (pos < text.length() && Character.isWhitespace(text.charAt(pos))) {
            pos++;
        }
    }

    private ConditionSyntaxException error(String expected) {
        return new ConditionSyntaxException(expected, pos + 1, text);
    }
}
