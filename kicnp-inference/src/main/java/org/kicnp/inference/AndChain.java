package org.kicnp.inference;

import java.util.ArrayList;
import java.util.List;

/**
 * Splits a script condition's text into the terms of a top-level {@code &&} chain, for {@link SimpleCondition}: a
 * lexical scan (quotes, regular expressions, brackets), not a parse, that answers only where the split is certain.
 */
final class AndChain {
    private AndChain() {
    }

    /**
     * The terms of {@code source} read as {@code T1 && T2 && ... && Tn} (one trailing ';' dropped), or an empty list
     * when it cannot be read so with certainty: any top-level operator that binds less tightly than {@code &&}
     * ({@code ||}, {@code ??}, {@code ?:}, an assignment, {@code ,}, {@code ;}, {@code =>}) would make the split wrong,
     * and braces, template literals, comments or an unclosed string, bracket or regular expression make the scan
     * uncertain. Texts in quotes and regular expressions are skipped (a '/' starts one after an operator or an opening
     * bracket, as a JavaScript tokenizer decides; elsewhere it divides).
     */
    static List<String> terms(String source) {
        String text = source.strip();
        if (text.endsWith(";")) {
            text = text.substring(0, text.length() - 1);
        }
        List<String> terms = new ArrayList<>();
        int depth = 0;
        int start = 0;
        char previous = '('; // the last significant character: at the start a '/' opens a regular expression
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '{' || c == '}' || c == '`' || c == ';') {
                return List.of();
            }
            if (c == '"' || c == '\'') {
                int end = closing(text, i, c);
                if (end < 0) {
                    return List.of();
                }
                i = end;
                previous = c;
                continue;
            }
            if (c == '/') {
                if (i + 1 < text.length() && (text.charAt(i + 1) == '/' || text.charAt(i + 1) == '*')) {
                    return List.of(); // a comment
                }
                if ("(,=:[!&|?+-*%<>~^".indexOf(previous) >= 0) {
                    int end = regexEnd(text, i);
                    if (end < 0) {
                        return List.of();
                    }
                    i = end;
                    previous = 'x'; // a regular expression is a value
                    continue;
                }
            }
            if (c == '(' || c == '[') {
                depth++;
            } else if (c == ')' || c == ']') {
                if (--depth < 0) {
                    return List.of();
                }
            } else if (depth == 0) {
                if (c == '&' && i + 1 < text.length() && text.charAt(i + 1) == '&') {
                    terms.add(text.substring(start, i));
                    i++;
                    start = i + 1;
                    previous = '&';
                    continue;
                }
                if (c == '|' && i + 1 < text.length() && text.charAt(i + 1) == '|' || c == '?' || c == ','
                        || c == ':' || c == '=' && assignsOrArrow(text, i)) {
                    return List.of();
                }
            }
            if (!Character.isWhitespace(c)) {
                previous = c;
            }
        }
        if (depth != 0) {
            return List.of();
        }
        terms.add(text.substring(start));
        return terms;
    }

    /** The index of the quote closing the text literal opened at {@code open}, or -1. */
    private static int closing(String text, int open, char quote) {
        for (int i = open + 1; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '\\') {
                i++;
            } else if (c == quote) {
                return i;
            } else if (c == '\n' || c == '\r') {
                return -1;
            }
        }
        return -1;
    }

    /** The index of the last character of the regular expression opened at {@code open} (its flags), or -1. */
    private static int regexEnd(String text, int open) {
        boolean inClass = false;
        for (int i = open + 1; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '\\') {
                i++;
            } else if (c == '[') {
                inClass = true;
            } else if (c == ']') {
                inClass = false;
            } else if (c == '\n' || c == '\r') {
                return -1;
            } else if (c == '/' && !inClass) {
                int end = i;
                while (end + 1 < text.length() && Character.isLetter(text.charAt(end + 1))) {
                    end++;
                }
                return end;
            }
        }
        return -1;
    }

    /**
     * Whether the '=' at {@code i} is an assignment or the start of '=>' (both bind less tightly than {@code &&}), not
     * part of ==, ===, !=, !==, <= or >=.
     */
    private static boolean assignsOrArrow(String text, int i) {
        char before = i > 0 ? text.charAt(i - 1) : ' ';
        char after = i + 1 < text.length() ? text.charAt(i + 1) : ' ';
        if (after == '=' || after == '>') {
            return after == '>'; // '==' is a comparison; '=>' an arrow function, which && does not bind
        }
        return before != '=' && before != '!' && before != '<' && before != '>';
    }
}
