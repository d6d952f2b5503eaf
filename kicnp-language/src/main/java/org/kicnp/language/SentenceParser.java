package org.kicnp.language;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * The sentence parser: tokenizes, peels off what surrounds the clause (a robot's name as vocative, "please" and
 * "thank you", fillers such as "um", and correction markers such as "no," "actually" and "instead"), then tries the
 * rules in a fixed order — answer, greeting, name, verb clause, verbless request — and takes the first that reads
 * the whole clause. Nothing matches: {@link ParseResult.NotUnderstood}, never a guess. Immutable and thread-safe.
 */
public final class SentenceParser {
    /**
     * The longest sentence read, in characters: far more than anyone says in one breath. A longer one (a paste) is not
     * understood, and its reason does not quote it, so what the parser agent asserts stays small.
     */
    public static final int MAX_LENGTH = 1_000;

    private static final Set<String> FILLERS = Set.of("um", "uh", "er", "erm", "hmm", "oh", "well", "ah", "so", "just");
    /** "please" and how it is typed in a hurry. */
    private static final Set<String> PLEASE = Set.of("please", "pls", "plz", "plse");
    private static final Set<String> CORRECTIONS = Set.of("no", "nope", "actually", "sorry", "oops", "oh no", "no no",
            "wait no", "no sorry");

    private final Lexicon lexicon;
    private final Tokenizer tokenizer = new Tokenizer();
    private final FixedExpressions fixed;
    private final CaseGrammar grammar;

    private SentenceParser(Lexicon lexicon) {
        this.lexicon = lexicon;
        this.fixed = new FixedExpressions(lexicon);
        this.grammar = new CaseGrammar(lexicon);
    }

    /** A parser over the scenario's lexicon. */
    public static SentenceParser standard() {
        return new SentenceParser(Lexicon.standard());
    }

    /** A parser over a given (usually extended) lexicon. */
    public static SentenceParser with(Lexicon lexicon) {
        return new SentenceParser(requireNonNull(lexicon, "lexicon"));
    }

    /** Parses a sentence said with no particular expectation. */
    public ParseResult parse(String sentence) {
        return parse(sentence, Expectation.NONE);
    }

    /** Parses a sentence said in answer to a question that expects a name or a drink. */
    public ParseResult parse(String sentence, Expectation expectation) {
        requireNonNull(sentence, "sentence");
        requireNonNull(expectation, "expectation");
        if (sentence.strip().length() > MAX_LENGTH) {
            return ParseResult.NotUnderstood.because("The sentence is " + sentence.strip().length()
                    + " characters long; at most " + MAX_LENGTH + " are read.");
        }
        Reading u = new Reading(sentence.strip(), expectation);
        List<List<Token>> segments = segments(tokenizer.tokenize(sentence));
        if (segments.isEmpty()) {
            return ParseResult.NotUnderstood.because("Nothing was said.");
        }
        List<Token> clause = surroundings(segments, u);
        if (clause.isEmpty()) {
            if (u.correction && u.thanked) { // "No, thanks": the comma made "no" look like a correction marker
                u.correction = false;
                return new ParseResult.Parsed(u.frame(Act.YES_NO_ANSWER, java.util.Map.of(Case.POLARITY,
                        Filler.known("no", SemanticClass.ANSWER, "no"))));
            }
            if (u.thanked) {
                return new ParseResult.Parsed(FixedExpressions.thanks(u));
            }
            return ParseResult.NotUnderstood.because("Only '" + u.text + "' was said: no clause to understand.");
        }
        return clause(clause, u).<ParseResult>map(ParseResult.Parsed::new)
                .orElseGet(() -> ParseResult.NotUnderstood.because(reason(clause, u)));
    }

    private Optional<CaseFrame> clause(List<Token> t, Reading u) {
        Optional<CaseFrame> f = fixed.answer(t, u);
        if (f.isEmpty()) {
            f = fixed.greeting(t, u);
        }
        if (f.isEmpty()) {
            f = fixed.name(t, u);
        }
        if (f.isEmpty()) {
            f = grammar.verbClause(t, u);
        }
        if (f.isEmpty()) {
            f = grammar.verblessRequest(t, u);
        }
        return f;
    }

    /** Splits at commas, dropping fillers, "please" and "thank you" (remembered as politeness). */
    private static List<List<Token>> segments(List<Token> tokens) {
        List<List<Token>> out = new ArrayList<>();
        List<Token> current = new ArrayList<>();
        for (Token t : tokens) {
            if (t.isComma()) {
                out.add(current);
                current = new ArrayList<>();
            } else {
                current.add(t);
            }
        }
        out.add(current);
        out.removeIf(List::isEmpty);
        return out;
    }

    /** Takes vocatives, politeness and correction markers off the segments and joins what is left into one clause. */
    private List<Token> surroundings(List<List<Token>> segments, Reading u) {
        List<List<Token>> rest = new ArrayList<>();
        for (int s = 0; s < segments.size(); s++) {
            List<Token> seg = strip(segments.get(s), u);
            String words = FixedExpressions.words(seg, 0, seg.size());
            boolean more = segments.size() > 1;
            if (seg.isEmpty()) {
                continue;
            }
            Optional<String> robot = seg.size() <= 2 ? lexicon.robot(seg.getLast().word()) : Optional.empty();
            if (robot.isPresent() && u.vocative.isEmpty()
                    && (seg.size() == 1 || Set.of("hey", "ok", "okay", "dear").contains(seg.getFirst().word()))) {
                u.vocative = Optional.of(Filler.known(seg.getLast().surface(), SemanticClass.ROBOT, robot.get()));
            } else if (more && (CORRECTIONS.contains(words) || seg.getFirst().word().equals("not"))) {
                u.correction = true;
            } else {
                rest.add(seg);
            }
        }
        if (rest.size() > 1) { // "Hi, I'm Ken", "Yes, I'd like tea": the greeting or the yes adds nothing
            rest.removeIf(seg -> fixed.greeting(seg, new Reading("", Expectation.NONE)).isPresent());
        }
        if (rest.size() > 1 && FixedExpressions.polarity(FixedExpressions.words(rest.getFirst(), 0,
                rest.getFirst().size())).filter("yes"::equals).isPresent()) {
            rest.removeFirst();
        }
        List<Token> clause = new ArrayList<>();
        rest.forEach(clause::addAll);
        if (!clause.isEmpty() && clause.getFirst().word().equals("actually")) {
            u.correction = true;
            clause.removeFirst();
        }
        if (!clause.isEmpty() && clause.getLast().word().equals("instead")) {
            u.correction = true;
            clause.removeLast();
        }
        vocativeWithoutComma(clause, u);
        return clause;
    }

    /** "AIBO sit down", "sit down AIBO": a robot's name next to a verb is a vocative even without a comma. */
    private void vocativeWithoutComma(List<Token> clause, Reading u) {
        if (u.vocative.isPresent() || clause.size() < 2) {
            return;
        }
        Optional<String> first = lexicon.robot(clause.getFirst().word());
        if (first.isPresent() && lexicon.verb(clause.get(1).word()).isPresent()) {
            u.vocative = Optional.of(Filler.known(clause.getFirst().surface(), SemanticClass.ROBOT, first.get()));
            clause.removeFirst();
            return;
        }
        Optional<String> last = lexicon.robot(clause.getLast().word());
        if (last.isPresent() && lexicon.verb(clause.getFirst().word()).isPresent()) {
            Token robot = clause.removeLast();
            u.vocative = Optional.of(Filler.known(robot.surface(), SemanticClass.ROBOT, last.get()));
        }
    }

    /**
     * Drops fillers at the start, every "please" or "pls" (which marks a request) and "thanks"/"thx"/"thank you"
     * (which does not: "thanks blorf" is no request for a blorf).
     */
    private static List<Token> strip(List<Token> seg, Reading u) {
        List<Token> out = new ArrayList<>();
        for (int i = 0; i < seg.size(); i++) {
            String w = seg.get(i).word();
            if (PLEASE.contains(w)) {
                u.polite = true;
            } else if (w.equals("thanks") || w.equals("thx")
                    || w.equals("thank") && i + 1 < seg.size() && seg.get(i + 1).word().equals("you")) {
                u.thanked = true;
                i += w.equals("thank") ? 1 : 0;
            } else if (!(out.isEmpty() && FILLERS.contains(w))) {
                out.add(seg.get(i));
            }
        }
        return out;
    }

    private String reason(List<Token> clause, Reading u) {
        if (u.firstReason().isPresent()) {
            return u.firstReason().get();
        }
        for (Token t : clause) {
            if (t.isAlphabetic() && !lexicon.isKnownWord(t.word())) {
                return "The word '" + t.surface() + "' is not in the lexicon, and no rule of the grammar reads '"
                        + u.text + "'.";
            }
        }
        return u.firstWeakReason().orElse("No rule of the grammar reads '" + u.text + "'.");
    }
}
