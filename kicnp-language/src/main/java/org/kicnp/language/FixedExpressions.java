package org.kicnp.language;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

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
    /**
     * The expressions that say a name and nothing else, so a word the lexicon has is a name there too ("My name is
     * Will", "Call me Barry White"); after the others ("I am", "it is", "this is") it is not: "I am thirsty".
     */
    private static final Set<String> ONLY_NAMES = Set.of("my name is", "the name is", "name is", "i am called",
            "you can call me", "call me", "they call me", "people call me", "everyone calls me", "friends call me",
            "i go by", "is my name");
    /** Words that are in no name even after "my name is": "My name is not Ken", "My name is a secret". */
    private static final Set<String> NEVER_IN_A_NAME = Set.of("not", "no", "and", "or", "but", "i", "you", "me", "it",
            "is", "am", "are", "was", "what", "who", "how", "why", "if", "so", "very", "too", "please", "thanks");

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
                Optional<CaseFrame> f = nameAt(t, n, t.size(), ONLY_NAMES.contains(before), u);
                if (f.isPresent()) {
                    return f;
                }
            }
        }
        for (String after : NAME_AFTER) {
            int n = after.split(" ").length;
            if (t.size() > n && words(t, t.size() - n, t.size()).equals(after)) {
                Optional<CaseFrame> f = nameAt(t, 0, t.size() - n, ONLY_NAMES.contains(after), u);
                if (f.isPresent()) {
                    return f;
                }
            }
        }
        return u.expectation == Expectation.NAME ? nameAt(t, 0, t.size(), false, u) : Optional.empty();
    }

    /** The name in {@code t[from, to)}; {@code onlyNames}: said after an expression that gives nothing but a name. */
    private Optional<CaseFrame> nameAt(List<Token> t, int from, int to, boolean onlyNames, Reading u) {
        if (to - from < 1 || to - from > 3) {
            return Optional.empty();
        }
        StringBuilder name = new StringBuilder();
        for (int i = from; i < to; i++) {
            Token w = t.get(i);
            if (onlyNames && lexicon.robot(w.word()).isPresent()) {
                u.miss("'" + w.surface() + "' is a robot's name, not a person's.");
                return Optional.empty();
            }
            if (!w.isAlphabetic() || lexicon.isKnownWord(w.word()) && !(onlyNames && nameWord(w.word()))) {
                return Optional.empty();
            }
            name.append(i > from ? " " : "").append(w.capitalized() ? w.surface()
                    : Character.toUpperCase(w.word().charAt(0)) + w.word().substring(1));
        }
        return Optional.of(u.frame(Act.NAME_STATEMENT, Map.of(Case.ATTRIBUTE,
                Filler.known(NounPhrases.text(t, from, to), SemanticClass.NAME, name.toString()))));
    }

    /**
     * A word the lexicon has that may still be part of a name said after "my name is": not a determiner, number,
     * preposition, time or direction ("Call me later" is no name), not a person's role ("user", "guest": frames of
     * the scenario, never a name to learn) and not one of {@link #NEVER_IN_A_NAME}.
     */
    private boolean nameWord(String word) {
        return !NEVER_IN_A_NAME.contains(word) && !Lexicon.DETERMINERS.contains(word) && !Lexicon.NUMBERS.containsKey(word)
                && lexicon.marker(word).isEmpty() && !Lexicon.TIMES.containsKey(word) && !Lexicon.DIRECTIONS.contains(word)
                && lexicon.noun(word).filter(n -> n.semanticClass() == SemanticClass.PERSON).isEmpty();
    }

    static String words(List<Token> t, int from, int to) {
        StringBuilder sb = new StringBuilder();
        for (int i = from; i < to; i++) {
            sb.append(i > from ? " " : "").append(t.get(i).word());
        }
        return sb.toString();
    }
}
