package org.kicnp.language;

import java.text.Normalizer;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Splits a sentence into {@link Token}s: lower-cases, keeps commas (and turns ; : dashes, and a . ! ? or … with more
 * words after it, into commas: "Hello! My name is Ken." is typed as one line), drops the final . ! ? and quotes, and
 * expands contractions ("I'm" → i am, "I'd" → i would, "it's" → it is, "don't" → do
 * not). A trailing {@code 's} that is not "is" is a possessive and is dropped ("Ken's" → ken).
 */
final class Tokenizer {
    private static final Map<String, String> CONTRACTIONS = Map.ofEntries(
            Map.entry("i'm", "i am"), Map.entry("im", "i am"), Map.entry("i'd", "i would"), Map.entry("i'll", "i will"),
            Map.entry("i've", "i have"), Map.entry("it's", "it is"), Map.entry("that's", "that is"),
            Map.entry("what's", "what is"), Map.entry("name's", "name is"), Map.entry("he's", "he is"),
            Map.entry("she's", "she is"), Map.entry("there's", "there is"), Map.entry("here's", "here is"),
            Map.entry("let's", "let us"), Map.entry("you're", "you are"), Map.entry("we'd", "we would"),
            Map.entry("can't", "can not"), Map.entry("cannot", "can not"), Map.entry("won't", "will not"),
            Map.entry("don't", "do not"), Map.entry("doesn't", "does not"), Map.entry("didn't", "did not"),
            Map.entry("wouldn't", "would not"), Map.entry("couldn't", "could not"), Map.entry("isn't", "is not"),
            Map.entry("y'know", "you know"), Map.entry("gimme", "give me"), Map.entry("wanna", "want to"));

    List<Token> tokenize(String sentence) {
        // NFC: an accent typed as a combining mark ("e" + U+0301) is one letter with it, "é".
        String text = Normalizer.normalize(sentence, Normalizer.Form.NFC).replace('\u2019', '\'').replace('\u2018', '\'');
        List<Token> out = new ArrayList<>();
        StringBuilder word = new StringBuilder();
        for (int i = 0, next; i <= text.length(); i = next) { // by code point: letters beyond U+FFFF are letters too
            int c = i < text.length() ? text.codePointAt(i) : ' ';
            next = i + Character.charCount(c);
            boolean inner = (c == '\'' || c == '-') && !word.isEmpty() && next < text.length()
                    && Character.isLetterOrDigit(text.codePointAt(next));
            if (Character.isLetterOrDigit(c) || inner || !word.isEmpty() && Token.isMark(c)) {
                word.appendCodePoint(c);
                continue;
            }
            flush(word, out);
            if (c == ',' || c == ';' || c == ':' || c == '-' || c == '\u2014' || c == '.' || c == '!' || c == '?'
                    || c == '\u2026') {
                if (!out.isEmpty() && !out.getLast().isComma()) {
                    out.add(Token.COMMA);
                }
            }
        }
        while (!out.isEmpty() && out.getLast().isComma()) {
            out.removeLast();
        }
        return out;
    }

    private static void flush(StringBuilder word, List<Token> out) {
        if (word.isEmpty()) {
            return;
        }
        String surface = word.toString();
        word.setLength(0);
        String lower = surface.toLowerCase(Locale.ROOT);
        String expanded = CONTRACTIONS.get(lower);
        if (expanded != null) {
            boolean first = true;
            for (String part : expanded.split(" ")) {
                out.add(new Token(part, first ? surface : part));
                first = false;
            }
        } else if (lower.endsWith("'s") && lower.length() > 2) {
            out.add(new Token(lower.substring(0, lower.length() - 2), surface.substring(0, surface.length() - 2)));
        } else {
            out.add(new Token(lower, surface));
        }
    }
}
