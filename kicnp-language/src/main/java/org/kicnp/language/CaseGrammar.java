package org.kicnp.language;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * The verb-centred part of the grammar. A clause is {@code [subject] verb [particle] argument*}: the subject is
 * "I" (then the verb must be one of wanting), "you" in "could you …" (the robot spoken to), or absent (an
 * imperative). Each argument is a noun phrase (object, or an indirect object before it for verbs of transfer), a
 * preposition and a noun phrase (the preposition marks the case), a direction (here, left: the goal) or a time.
 * The verb's case frame then decides: a case it does not take, or a case it needs and did not get, and the clause
 * is not understood. Also the verbless requests: "Tea", "Some coffee would be nice", "Make it tea".
 */
final class CaseGrammar {
    private enum Subject { NONE, I, YOU }

    private static final Set<String> ASKING = Set.of("can", "could", "would", "will");

    private final Lexicon lexicon;
    private final NounPhrases phrases;

    CaseGrammar(Lexicon lexicon) {
        this.lexicon = lexicon;
        this.phrases = new NounPhrases(lexicon);
    }

    /** A clause with a verb: a command, or a request with a verb of wanting or of bringing. */
    Optional<CaseFrame> verbClause(List<Token> t, Reading u) {
        int i = 0;
        Subject subject = Subject.NONE;
        if (t.size() > 2 && ASKING.contains(t.get(0).word()) && t.get(1).word().equals("you")) {
            subject = Subject.YOU;
            i = 2;
        } else if (t.size() > 2 && Set.of("can", "could", "may").contains(t.get(0).word()) && t.get(1).word().equals("i")) {
            subject = Subject.I;
            i = 2;
        } else if (t.size() > 1 && t.get(0).word().equals("let") && t.get(1).word().equals("me")) {
            subject = Subject.I;
            i = 2;
        } else if (t.size() > 1 && t.get(0).word().equals("i")) {
            subject = Subject.I;
            i = 1;
            while (i < t.size() - 1 && Set.of("would", "will", "rather", "really", "also").contains(t.get(i).word())) {
                i++;
            }
        }
        if (i >= t.size()) {
            return Optional.empty();
        }
        Token verbToken = t.get(i);
        Optional<Verb> found = subject == Subject.I ? lexicon.firstPersonVerb(verbToken.word())
                : lexicon.verb(verbToken.word());
        if (found.isEmpty()) {
            u.missWeakly("'" + verbToken.surface() + "' is not a verb the lexicon knows"
                    + (subject == Subject.I ? " after 'I'." : "."));
            return Optional.empty();
        }
        Verb verb = found.get();
        int verbAt = i++;
        if (i < t.size() && verb.particles().contains(t.get(i).word())) {
            i++;
        } else if (verb.particleRequired()) {
            u.miss("'" + verb.lemma() + "' needs one of " + verb.particles() + " after it.");
            return Optional.empty();
        }
        Map<Case, Filler> cases = new EnumMap<>(Case.class);
        cases.put(Case.ACTION, Filler.known(NounPhrases.text(t, verbAt, i),
                SemanticClass.ACTION, verb.action()));
        if (!arguments(t, i, verb, cases, u)) {
            return Optional.empty();
        }
        return decide(verb, subject, cases, u);
    }

    private boolean arguments(List<Token> t, int start, Verb verb, Map<Case, Filler> cases, Reading u) {
        int i = start;
        while (i < t.size()) {
            String w = t.get(i).word();
            int prepLength = prepositionLength(t, i);
            if (prepLength > 0) {
                String prep = FixedExpressions.words(t, i, i + prepLength);
                Optional<NounPhrases.Np> np = phrases.read(t, i + prepLength, 0);
                if (np.isEmpty()) {
                    return miss(u, "After '" + prep + "' a noun phrase is missing in '" + u.text + "'.");
                }
                Case c = caseFor(prep, np.get(), verb);
                Filler head = np.get().head();
                if (c == Case.INSTRUMENT && !head.known() && !verb.allowed().contains(c)
                        && verb.allowed().contains(Case.CO_AGENT)) { // "shake hands with ken": a name, said lower-case
                    c = Case.CO_AGENT;
                    head = Filler.known(head.text(), SemanticClass.PERSON,
                            Character.toUpperCase(head.value().charAt(0)) + head.value().substring(1));
                }
                if (!put(cases, c, head, verb, u)) {
                    return false;
                }
                i = np.get().end();
            } else if (Lexicon.TIMES.containsKey(w)) {
                if (!put(cases, Case.TIME, Filler.known(t.get(i).surface(), SemanticClass.TIME, Lexicon.TIMES.get(w)), verb, u)) {
                    return false;
                }
                i++;
            } else if (Lexicon.DIRECTIONS.contains(w)) {
                Case c = verb.allowed().contains(Case.GOAL) ? Case.GOAL : Case.LOCATION;
                if (!put(cases, c, Filler.known(t.get(i).surface(), SemanticClass.PLACE, w), verb, u)) {
                    return false;
                }
                i++;
            } else {
                Optional<NounPhrases.Np> np = phrases.read(t, i, 0);
                if (np.isEmpty()) {
                    return miss(u, "'" + t.get(i).surface() + "' does not fit the case frame of '" + verb.lemma() + "'.");
                }
                boolean indirect = verb.kind() == Verb.Kind.TRANSFER && !cases.containsKey(Case.OBJECT)
                        && !cases.containsKey(Case.RECIPIENT) && np.get().animate()
                        && phrases.read(t, np.get().end(), 0).isPresent();
                if (!put(cases, indirect ? Case.RECIPIENT : Case.OBJECT, np.get().head(), verb, u)) {
                    return false;
                }
                if (np.get().quantity().isPresent() && !put(cases, Case.QUANTITY, np.get().quantity().get(), verb, u)) {
                    return false;
                }
                i = np.get().end();
            }
        }
        for (Case c : verb.required()) {
            if (!cases.containsKey(c)) {
                String name = c.name().toLowerCase(java.util.Locale.ROOT).replace('_', '-');
                return miss(u, "'" + verb.lemma() + "' needs " + ("aeiou".indexOf(name.charAt(0)) >= 0 ? "an " : "a ")
                        + name + ".");
            }
        }
        return true;
    }

    private int prepositionLength(List<Token> t, int i) {
        for (int n = 3; n >= 1; n--) {
            if (i + n <= t.size() && lexicon.marker(FixedExpressions.words(t, i, i + n)).isPresent()) {
                return n;
            }
        }
        return 0;
    }

    private Case caseFor(String prep, NounPhrases.Np np, Verb verb) {
        Case c = verb.markers().containsKey(prep) ? verb.markers().get(prep) : lexicon.marker(prep).orElseThrow();
        if (c == Case.INSTRUMENT && np.animate()) {
            return Case.CO_AGENT;
        }
        if (c == Case.GOAL && prep.equals("to") && verb.kind() == Verb.Kind.TRANSFER && np.animate()) {
            return Case.RECIPIENT;
        }
        return c;
    }

    private static boolean put(Map<Case, Filler> cases, Case c, Filler f, Verb verb, Reading u) {
        if (!verb.allowed().contains(c)) {
            return miss(u, "'" + verb.lemma() + "' takes no " + c.name().toLowerCase(java.util.Locale.ROOT)
                    + " such as '" + f.text() + "'.");
        }
        if (cases.containsKey(c)) {
            return miss(u, "'" + verb.lemma() + "' has two fillers for its " + c.name().toLowerCase(java.util.Locale.ROOT) + ".");
        }
        cases.put(c, f);
        return true;
    }

    private Optional<CaseFrame> decide(Verb verb, Subject subject, Map<Case, Filler> cases, Reading u) {
        switch (verb.kind()) {
            case WANT, CORRECT -> {
                if (subject != Subject.I) {
                    u.miss("'" + verb.lemma() + "' is a wish of the speaker's and needs 'I'.");
                    return Optional.empty();
                }
                u.correction |= verb.kind() == Verb.Kind.CORRECT;
                cases.putIfAbsent(Case.RECIPIENT, Filler.known("I", SemanticClass.PERSON, "speaker"));
                return drinkRequest(cases, u);
            }
            case TRANSFER -> {
                if (subject == Subject.I) {
                    return Optional.empty();
                }
                if (subject == Subject.YOU) {
                    cases.put(Case.AGENT, Filler.known("you", SemanticClass.ROBOT, "addressee"));
                }
                Filler object = cases.get(Case.OBJECT);
                boolean drink = object.semanticClass() == SemanticClass.DRINK || !object.known();
                if (u.vocative.isEmpty() && drink) {
                    return drinkRequest(cases, u);
                }
                return Optional.of(u.frame(Act.ROBOT_COMMAND, cases));
            }
            case COMMAND -> {
                if (subject == Subject.I) {
                    return Optional.empty();
                }
                if (subject == Subject.YOU) {
                    cases.put(Case.AGENT, Filler.known("you", SemanticClass.ROBOT, "addressee"));
                }
                return Optional.of(u.frame(Act.ROBOT_COMMAND, cases));
            }
        }
        throw new IllegalStateException("Unhandled verb kind " + verb.kind() + ".");
    }

    /** The verbless requests: a noun phrase alone, "X would be nice", "make it X", "how about X". */
    Optional<CaseFrame> verblessRequest(List<Token> t, Reading u) {
        Map<Case, Filler> cases = new EnumMap<>(Case.class);
        boolean clearly = u.polite || u.correction || u.expectation == Expectation.DRINK;
        int from = 0;
        int to = t.size();
        if (t.size() > 2 && t.get(0).word().equals("make") && t.get(1).word().equals("it")) {
            u.correction = true;
            clearly = true;
            from = 2;
        } else if (t.size() > 2 && Set.of("how", "what").contains(t.get(0).word()) && t.get(1).word().equals("about")) {
            clearly = true;
            from = 2;
        } else {
            int evaluation = evaluation(t);
            if (evaluation >= 0) {
                clearly = true;
                to = evaluation;
            }
        }
        Optional<NounPhrases.Np> np = phrases.read(t.subList(0, to), from, 0);
        if (np.isEmpty()) {
            return Optional.empty();
        }
        if (np.get().end() != to && !beneficiary(t.subList(0, to), np.get().end(), cases)) {
            return Optional.empty();
        }
        cases.put(Case.OBJECT, np.get().head());
        np.get().quantity().ifPresent(q -> cases.put(Case.QUANTITY, q));
        if (!np.get().head().known() && !clearly) {
            u.miss("'" + np.get().head().text() + "' is not in the lexicon, and nothing marks the sentence as a request.");
            return Optional.empty();
        }
        return drinkRequest(cases, u);
    }

    /** "Tea for Ken", "Coffee for me": a recipient after the drink, and nothing more. */
    private boolean beneficiary(List<Token> t, int at, Map<Case, Filler> cases) {
        if (!t.get(at).word().equals("for")) {
            return false;
        }
        Optional<NounPhrases.Np> np = phrases.read(t, at + 1, 0);
        if (np.isEmpty() || np.get().end() != t.size() || !np.get().animate()) {
            return false;
        }
        cases.put(Case.RECIPIENT, np.get().head());
        return true;
    }

    /** The index where "would be nice", "is fine", "sounds good" starts, or -1. */
    private static int evaluation(List<Token> t) {
        int n = t.size();
        if (n >= 3 && Lexicon.EVALUATIVES.contains(t.get(n - 1).word())) {
            String before = t.get(n - 2).word();
            if (n >= 4 && before.equals("be") && Set.of("would", "will").contains(t.get(n - 3).word())) {
                return n - 3;
            }
            if (before.equals("is") || before.equals("sounds")) {
                return n - 2;
            }
        }
        return -1;
    }

    private static Optional<CaseFrame> drinkRequest(Map<Case, Filler> cases, Reading u) {
        Filler object = cases.get(Case.OBJECT);
        if (object.known() && object.semanticClass() != SemanticClass.DRINK) {
            u.miss("'" + object.text() + "' is not something to drink.");
            return Optional.empty();
        }
        if (!object.known()) {
            cases.put(Case.OBJECT, new Filler(object.text(), SemanticClass.DRINK, object.value(), false));
        }
        return Optional.of(u.frame(Act.DRINK_REQUEST, cases));
    }

    private static boolean miss(Reading u, String reason) {
        u.miss(reason);
        return false;
    }
}
