package org.kicnp.language;

import java.util.List;
import java.util.Optional;

/**
 * Reads one noun phrase: a pronoun, a robot's name, a proper name (capitalised words the lexicon does not know,
 * up to three), or {@code [quantity] [determiner] modifier* head}, where the quantity is "a", "some", "two", "a cup
 * of", "a little", "another". A head the lexicon does not know is accepted as an unknown noun only if it is one
 * lower-case word, so "a lemonade" is a phrase and "blorf zap" is not.
 */
final class NounPhrases {
    /** The phrase read: its head filler, the quantity if one was said, and the index after it. */
    record Np(Filler head, Optional<Filler> quantity, int end) {
        boolean animate() {
            SemanticClass c = head.semanticClass();
            return c == SemanticClass.PERSON || c == SemanticClass.ROBOT || c == SemanticClass.NAME;
        }
    }

    private final Lexicon lexicon;

    NounPhrases(Lexicon lexicon) {
        this.lexicon = lexicon;
    }

    /**
     * Reads a phrase starting at {@code from}. Capitalisation marks a proper name except at {@code sentenceStart},
     * where every word is capitalised.
     */
    Optional<Np> read(List<Token> t, int from, int sentenceStart) {
        int i = from;
        Optional<Filler> quantity = Optional.empty();
        if (i >= t.size()) {
            return Optional.empty();
        }
        int q = quantity(t, i);
        if (q > i) {
            quantity = Optional.of(Filler.known(text(t, i, q), SemanticClass.QUANTITY, quantityValue(t, i, q)));
            i = q;
        }
        if (i < t.size() && Lexicon.DETERMINERS.contains(t.get(i).word()) && !Lexicon.NUMBERS.containsKey(t.get(i).word())) {
            i++;
        }
        int headAt = i;
        while (i + 1 < t.size() && Lexicon.MODIFIERS.contains(t.get(i).word()) && headable(t.get(i + 1))) {
            i++;
        }
        if (i >= t.size()) {
            return Optional.empty();
        }
        Token head = t.get(i);
        Optional<Lexicon.Noun> noun = lexicon.noun(head.word());
        if (noun.isPresent()) {
            Filler f = Filler.known(text(t, from, i + 1), noun.get().semanticClass(), noun.get().value());
            return Optional.of(new Np(f, quantity, i + 1));
        }
        if (!head.isAlphabetic() || lexicon.isKnownWord(head.word())) {
            return Optional.empty();
        }
        if (head.capitalized() && i != sentenceStart && headAt == from) {
            int end = i;
            StringBuilder name = new StringBuilder();
            while (end < t.size() && end - i < 3 && t.get(end).capitalized() && t.get(end).isAlphabetic()
                    && !lexicon.isKnownWord(t.get(end).word())) {
                name.append(name.isEmpty() ? "" : " ").append(t.get(end).surface());
                end++;
            }
            return Optional.of(new Np(Filler.known(name.toString(), SemanticClass.PERSON, name.toString()),
                    Optional.empty(), end));
        }
        Filler unknown = new Filler(text(t, from, i + 1), SemanticClass.THING, head.word(), false);
        return Optional.of(new Np(unknown, quantity, i + 1));
    }

    private boolean headable(Token next) {
        return lexicon.noun(next.word()).isPresent() || Lexicon.MODIFIERS.contains(next.word())
                || (next.isAlphabetic() && !lexicon.isKnownWord(next.word()));
    }

    /** The index after a quantity starting at {@code i}, or {@code i} if there is none. */
    private int quantity(List<Token> t, int i) {
        String w = t.get(i).word();
        if ((w.equals("a")) && i + 1 < t.size() && (t.get(i + 1).word().equals("little"))) {
            return i + 2;
        }
        if (w.equals("a") && i + 2 < t.size() && t.get(i + 1).word().equals("bit") && t.get(i + 2).word().equals("of")) {
            return i + 3;
        }
        if (Lexicon.NUMBERS.containsKey(w)) {
            if (i + 2 < t.size() && isUnit(t.get(i + 1).word()) && t.get(i + 2).word().equals("of")) {
                return i + 3;
            }
            return i + 1;
        }
        return w.equals("some") || w.equals("more") || w.equals("another") ? i + 1 : i;
    }

    private static String quantityValue(List<Token> t, int from, int to) {
        String w = t.get(from).word();
        if (to - from >= 2 && (t.get(from + 1).word().equals("little") || t.get(from + 1).word().equals("bit"))) {
            return "some";
        }
        Integer n = Lexicon.NUMBERS.get(w);
        if (n == null) {
            return w;
        }
        if (to - from == 3) {
            String unit = singular(t.get(from + 1).word());
            return n + " " + unit + (n > 1 ? "s" : "");
        }
        return String.valueOf(n);
    }

    private static boolean isUnit(String word) {
        return Lexicon.UNITS.contains(singular(word));
    }

    private static String singular(String word) {
        return word.endsWith("es") && Lexicon.UNITS.contains(word.substring(0, word.length() - 2))
                ? word.substring(0, word.length() - 2)
                : word.endsWith("s") && Lexicon.UNITS.contains(word.substring(0, word.length() - 1))
                ? word.substring(0, word.length() - 1) : word;
    }

    static String text(List<Token> t, int from, int to) {
        StringBuilder sb = new StringBuilder();
        for (int i = from; i < to; i++) {
            sb.append(i > from ? " " : "").append(t.get(i).surface());
        }
        return sb.toString();
    }
}
