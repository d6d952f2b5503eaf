package org.kicnp.script;

/**
 * Turns typographic quotes used as string delimiters into ASCII quotes, so a script copied from the paper
 * ({@code Sendmsg(s.mMouth, “Hi! Nice to meet you.”);}) parses.
 *
 * <p>Outside string literals, template literals and comments, {@code “} or {@code ”} opens a string that the
 * next {@code “} or {@code ”} closes (both become {@code "}), and {@code ‘} or {@code ’} opens one that the next
 * {@code ‘} or {@code ’} closes (both become {@code '}). An ASCII quote of the same kind inside such a string
 * is escaped. Typographic quotes inside ASCII-quoted strings, template literals and comments are left alone, as
 * is an unterminated typographic string (the parser then reports it). Regular-expression literals are not
 * recognised; a typographic quote inside one would be converted. Line and column numbers are unchanged except
 * after an escaped ASCII quote.
 */
final class QuoteNormalizer {

    private QuoteNormalizer() {
    }

    /** Returns the source with typographic string delimiters replaced; the same instance when there are none. */
    static String normalize(String source) {
        if (!hasTypographicQuote(source)) {
            return source;
        }
        StringBuilder out = new StringBuilder(source.length() + 8);
        int i = 0;
        int n = source.length();
        while (i < n) {
            char c = source.charAt(i);
            if (c == '"' || c == '\'' || c == '`') {
                int end = endOfAsciiLiteral(source, i, c);
                out.append(source, i, end);
                i = end;
            } else if (c == '/' && i + 1 < n && source.charAt(i + 1) == '/') {
                int end = source.indexOf('\n', i);
                end = end < 0 ? n : end;
                out.append(source, i, end);
                i = end;
            } else if (c == '/' && i + 1 < n && source.charAt(i + 1) == '*') {
                int end = source.indexOf("*/", i + 2);
                end = end < 0 ? n : end + 2;
                out.append(source, i, end);
                i = end;
            } else if (isDouble(c) || isSingle(c)) {
                i = typographicLiteral(source, i, out);
            } else {
                out.append(c);
                i++;
            }
        }
        return out.toString();
    }

    private static boolean hasTypographicQuote(String source) {
        for (int i = 0; i < source.length(); i++) {
            char c = source.charAt(i);
            if (isDouble(c) || isSingle(c)) {
                return true;
            }
        }
        return false;
    }

    /** Index just past the ASCII literal opened at {@code start}, honouring backslash escapes. */
    private static int endOfAsciiLiteral(String source, int start, char quote) {
        int i = start + 1;
        while (i < source.length()) {
            char c = source.charAt(i);
            if (c == '\\') {
                i += 2;
            } else if (c == quote) {
                return i + 1;
            } else if (c == '\n' && quote != '`') {
                return i;
            } else {
                i++;
            }
        }
        return source.length();
    }

    /** Converts the typographic literal opened at {@code start} and returns the index just past it. */
    private static int typographicLiteral(String source, int start, StringBuilder out) {
        boolean dbl = isDouble(source.charAt(start));
        char ascii = dbl ? '"' : '\'';
        int i = start + 1;
        StringBuilder body = new StringBuilder();
        while (i < source.length()) {
            char c = source.charAt(i);
            if (c == '\n') {
                break;
            }
            if (dbl ? isDouble(c) : isSingle(c)) {
                out.append(ascii).append(body).append(ascii);
                return i + 1;
            }
            if (c == '\\' && i + 1 < source.length()) {
                body.append(c).append(source.charAt(i + 1));
                i += 2;
                continue;
            }
            if (c == ascii) {
                body.append('\\');
            }
            body.append(c);
            i++;
        }
        out.append(source.charAt(start));
        return start + 1;
    }

    private static boolean isDouble(char c) {
        return c == '\u201C' || c == '\u201D';
    }

    private static boolean isSingle(char c) {
        return c == '\u2018' || c == '\u2019';
    }
}
