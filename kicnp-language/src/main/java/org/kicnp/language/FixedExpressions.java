package org.kicnp.language;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * The fixed expressions, which have no verb frame worth the name: yes/no answers, greetings, and the ways of saying
 * one's name ("My name is Ken", "I'm Ken", "Call me Ken", "They call me Ken Smith", "It's Ken", and "Ken" alone when
 * the dialogue expects a name). A name is one to three words the lexicon does not know.
 */
final class FixedExpressions {
    private static final List<String> YES = List.of("yes", "yeah", "yep", "yup", "sure", "ok", "okay", "certainly",
            "of course", "yes i do", "that is right", "right", "correct", "all right", "alright", "yes i would");
    private static final List<String> NO = List.of("no", "nope", "nah", "not really", "no way", "no i do not",
            "no i would not", "not now", "no no");
    private static final Map<String, String> GREETINGS = Map.ofEntries(Map.entry("hello", "hello"),
            Map.entry("hi", "hello"), Map.entry("hey", "hello"), Map.entry("hello there", "hello"),
            Map.entry("hi there", "hello"), Map.entry("good morning", "hello"), Map.entry("good afternoon", "hello"),
            Map.entry("good evening", "hello"), Map.entry("good day", "hello"), Map.entry("greetings", "hello"),
            Map.entry("nice to meet you", "hello"), Map.entry("how are you", "hello"),
            Map.entry("how do you do", "hello"), Map.entry("goodbye", "goodbye"), Map.entry("bye", "goodbye"),
            Map.entry("bye bye", "goodbye"), Map.entry("good bye", "goodbye"), Map.entry("see you", "goodbye"),
            Map.entry("see you later", "goodbye"), Map.entry("good night", "goodbye"));
    private static final List<String> NAME_BEFORE = List.of("my name is", "the name is", "name is", "i am called",
            "i am", "you can call me", "call me", "they call me", "people call me", "everyone calls me",
            "friends call me", "it is me", "it is", "this is", "i go by");
    private static final List<String> NAME_AFTER = List.of("is my name");

    private final Lexicon lexicon;

    FixedExpressions(Lexicon lexicon) {
        this.lexicon = lexicon;
    }

    /** The polarity of an answer, if the words are one. */
    static Optional<String> polarity(String words) {
        if (YES.contains(words)) {
            return Optional.of("yes");
        }
        return NO.contains(words) ? Optional.of("no") : Optional.empty();
    }

    Optional<CaseFrame> answer(List<Token> t, Reading u) {
        String words = words(t, 0, t.size());
        return polarity(words).map(p -> u.frame(Act.YES_NO_ANSWER,
                Map.of(Case.POLARITY, Filler.known(NounPhrases.text(t, 0, t.size()), SemanticClass.ANSWER, p))));
    }

    /** A greeting, optionally followed by a robot's name ("Hello Robovie"). */
    Optional<CaseFrame> greeting(List<Token> t, Reading u) {
        int end = t.size();
        Optional<String> robot = lexicon.robot(t.getLast().word());
        if (robot.isPresent() && end > 1) {
            end--;
        }
        String greeting = GREETINGS.get(words(t, 0, end));
        if (greeting == null) {
            return Optional.empty();
        }
        Map<Case, Filler> cases = new EnumMap<>(Case.class);
        cases.put(Case.ACTION, Filler.known(NounPhrases.text(t, 0, end), SemanticClass.ACTION, greeting));
        if (end < t.size()) {
            cases.put(Case.RECIPIENT, Filler.known(t.getLast().surface(), SemanticClass.ROBOT, robot.orElseThrow()));
        }
        return Optional.of(u.frame(Act.GREETING, cases));
    }

    /** "Thank you" alone. */
    static CaseFrame thanks(Reading u) {
        return u.frame(Act.GREETING, Map.of(Case.ACTION, Filler.known("thank you", SemanticClass.ACTION, "thanks")));
    }

    /** A name statement; a bare name only when the dialogue expects one. */
    Optional<CaseFrame> name(List<Token> t, Reading u) {
        for (String before : NAME_BEFORE) {
            int n = before.split(" ").length;
            if (t.size() > n && words(t, 0, n).equals(before)) {
                Optional<CaseFrame> f = nameAt(t, n, t.size(), u);
                if (f.isPresent()) {
                    return f;
                }
            }
        }
        for (String after : NAME_AFTER) {
            int n = after.split(" ").length;
            if (t.size() > n && words(t, t.size() - n, t.size()).equals(after)) {
                Optional<CaseFrame> f = nameAt(t, 0, t.size() - n, u);
                if (f.isPresent()) {
                    return f;
                }
            }
        }
        return u.expectation == Expectation.NAME ? nameAt(t, 0, t.size(), u) : Optional.empty();
    }

    private Optional<CaseFrame> nameAt(List<Token> t, int from, int to, Reading u) {
        if (to - from < 1 || to - from > 3) {
            return Optional.empty();
        }
        StringBuilder name = new StringBuilder();
        for (int i = from; i < to; i++) {
            Token w = t.get(i);
            if (!w.isAlphabetic() || lexicon.isKnownWord(w.word())) {
                return Optional.empty();
            }
            name.append(i > from ? " " : "").append(w.capitalized() ? w.surface()
                    : Character.toUpperCase(w.word().charAt(0)) + w.word().substring(1));
        }
        return Optional.of(u.frame(Act.NAME_STATEMENT, Map.of(Case.ATTRIBUTE,
                Filler.known(NounPhrases.text(t, from, to), SemanticClass.NAME, name.toString()))));
    }

    static String words(List<Token> t, int from, int to) {
        StringBuilder sb = new StringBuilder();
        for (int i = from; i < to; i++) {
            sb.append(i > from ? " " : "").append(t.get(i).word());
        }
        return sb.toString();
    }
}
