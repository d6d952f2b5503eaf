package org.kicnp.language;

import static java.util.Objects.requireNonNull;
import static org.kicnp.language.Case.CO_AGENT;
import static org.kicnp.language.Case.GOAL;
import static org.kicnp.language.Case.INSTRUMENT;
import static org.kicnp.language.Case.LOCATION;
import static org.kicnp.language.Case.OBJECT;
import static org.kicnp.language.Case.QUANTITY;
import static org.kicnp.language.Case.RECIPIENT;
import static org.kicnp.language.Case.SOURCE;
import static org.kicnp.language.Case.TIME;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.kicnp.language.Verb.Kind;

/**
 * The words the grammar knows: nouns with their semantic class and normalised value (the robots' names, the drinks,
 * places, persons, things), verbs with their case frames, case-marking prepositions, and the closed classes the
 * rules use. Immutable; {@link #standard()} is the scenario's lexicon and {@link #toBuilder()} extends it.
 */
public final class Lexicon {
    /** A noun's meaning: the value it normalises to and its class. */
    public record Noun(String value, SemanticClass semanticClass) {
        public Noun {
            requireNonNull(value, "value");
            requireNonNull(semanticClass, "semanticClass");
        }
    }

    static final Set<String> DETERMINERS = Set.of("the", "a", "an", "some", "my", "your", "his", "her", "this", "that",
            "these", "those", "another", "more", "any", "our", "their");
    static final Map<String, Integer> NUMBERS = Map.of("a", 1, "an", 1, "one", 1, "two", 2, "three", 3, "four", 4,
            "five", 5, "1", 1, "2", 2, "3", 3);
    static final Set<String> UNITS = Set.of("cup", "glass", "mug", "bottle", "pot", "can", "jug");
    static final Set<String> MODIFIERS = Set.of("hot", "cold", "iced", "warm", "green", "black", "orange", "apple",
            "fresh", "sweet", "strong", "sparkling", "mineral", "big", "small", "little", "large", "nice", "red", "blue",
            "new", "old", "same", "other", "white", "front", "back");
    static final Set<String> DIRECTIONS = Set.of("here", "there", "home", "away", "back", "forward", "forwards",
            "backward", "backwards", "left", "right", "around", "over", "outside", "inside", "closer");
    static final Map<String, String> TIMES = Map.of("now", "now", "later", "later", "soon", "soon",
            "immediately", "now", "again", "again", "first", "first", "today", "today", "tomorrow", "tomorrow");
    static final Set<String> EVALUATIVES = Set.of("nice", "great", "good", "lovely", "perfect", "fine", "wonderful",
            "ok", "okay", "best", "better");
    /** Words that are never a name, so "I am thirsty" is not a name statement. */
    static final Set<String> FUNCTION_WORDS = Set.of("i", "am", "is", "are", "be", "was", "would", "will", "can",
            "could", "may", "do", "does", "not", "no", "yes", "please", "thanks", "thank", "you", "me", "it", "and",
            "or", "but", "so", "very", "just", "really", "too", "also", "thirsty", "hungry", "tired", "happy", "sorry",
            "ready", "done", "busy", "well", "sure", "like", "want", "what", "who", "how", "why", "where", "when",
            "hello", "hi", "hey", "bye", "goodbye", "name", "called", "call", "of", "actually", "instead", "make",
            "let", "us", "him", "them", "we", "they", "he", "she", "if", "then", "to", "with", "from", "at", "for",
            "in", "on", "by", "near", "into", "um", "uh", "oh", "hmm", "have", "get", "had", "said", "meant");

    private final Map<String, Noun> nouns;
    private final Map<String, Verb> verbs;
    private final Map<String, Case> markers;
    private final Set<String> particles;

    private Lexicon(Map<String, Noun> nouns, Map<String, Verb> verbs, Map<String, Case> markers) {
        this.nouns = Map.copyOf(nouns);
        this.verbs = Map.copyOf(verbs);
        this.markers = Map.copyOf(markers);
        Set<String> p = new HashSet<>();
        verbs.values().forEach(v -> p.addAll(v.particles()));
        this.particles = Set.copyOf(p);
    }

    /** A noun by its lower-case form, also found through a plural -s ("cups", "teas"). */
    public Optional<Noun> noun(String word) {
        Noun n = nouns.get(word);
        if (n == null && word.length() > 3 && word.endsWith("s")) {
            n = nouns.get(word.substring(0, word.length() - 1));
        }
        return Optional.ofNullable(n);
    }

    /** A verb by its base form. */
    public Optional<Verb> verb(String word) {
        return Optional.ofNullable(verbs.get(word));
    }

    /** A robot's canonical name ({@code AIBO}, {@code Scout}) by the word said; not the pronoun "you". */
    public Optional<String> robot(String word) {
        return noun(word).filter(n -> n.semanticClass() == SemanticClass.ROBOT && !n.value().equals("addressee"))
                .map(Noun::value);
    }

    /** The default case a preposition marks, one or two words ("next to"). */
    public Optional<Case> marker(String preposition) {
        return Optional.ofNullable(markers.get(preposition));
    }

    /** The known drinks' values. */
    public Set<String> drinks() {
        Set<String> out = new HashSet<>();
        nouns.values().stream().filter(n -> n.semanticClass() == SemanticClass.DRINK).forEach(n -> out.add(n.value()));
        return Set.copyOf(out);
    }

    /** True if the word has any entry or is one the rules use, so it cannot be a proper name. */
    public boolean isKnownWord(String word) {
        return noun(word).isPresent() || verbs.containsKey(word) || verbs.containsKey("i:" + word)
                || particles.contains(word)
                || markers.containsKey(word)
                || DETERMINERS.contains(word) || NUMBERS.containsKey(word) || MODIFIERS.contains(word)
                || DIRECTIONS.contains(word) || TIMES.containsKey(word) || EVALUATIVES.contains(word)
                || FUNCTION_WORDS.contains(word) || UNITS.contains(word);
    }

    /** A builder holding this lexicon's entries, to add words to. */
    public Builder toBuilder() {
        return new Builder(nouns, verbs, markers);
    }

    /** The lexicon of the paper's scenario: four robots, four drinks, the room, and the robots' actions. */
    public static Lexicon standard() {
        Builder b = new Builder(Map.of(), Map.of(), Map.of());
        for (String robot : List.of("Robovie", "PINO", "Scout", "AIBO")) {
            b.noun(robot.toLowerCase(java.util.Locale.ROOT), robot, SemanticClass.ROBOT);
        }
        for (String drink : List.of("tea", "coffee", "water", "juice")) {
            b.noun(drink, drink, SemanticClass.DRINK);
        }
        b.noun("tee", "tea", SemanticClass.DRINK); // as the paper's Table 5 spells it
        for (String place : List.of("door", "table", "kitchen", "room", "window", "chair", "corner", "desk", "sofa",
                "charger", "entrance", "wall", "bed", "couch", "exit", "hall", "station")) {
            b.noun(place, place, SemanticClass.PLACE);
        }
        for (String person : List.of("user", "man", "woman", "guest", "friend", "visitor", "everyone", "everybody",
                "people", "child", "boy", "girl")) {
            b.noun(person, person, SemanticClass.PERSON);
        }
        for (String thing : List.of("ball", "bone", "cup", "glass", "mug", "bottle", "box", "book", "tray", "toy",
                "hand", "hands", "head", "tail", "light", "lights", "paw")) {
            b.noun(thing, thing, SemanticClass.THING);
        }
        b.noun("me", "speaker", SemanticClass.PERSON).noun("i", "speaker", SemanticClass.PERSON)
                .noun("us", "speaker", SemanticClass.PERSON).noun("you", "addressee", SemanticClass.ROBOT)
                .noun("him", "him", SemanticClass.PERSON).noun("her", "her", SemanticClass.PERSON)
                .noun("them", "them", SemanticClass.PERSON).noun("it", "it", SemanticClass.THING);
        b.marker("to", GOAL).marker("into", GOAL).marker("towards", GOAL).marker("toward", GOAL).marker("onto", GOAL)
                .marker("from", SOURCE).marker("with", INSTRUMENT).marker("for", RECIPIENT).marker("at", LOCATION)
                .marker("near", LOCATION).marker("by", LOCATION).marker("beside", LOCATION).marker("behind", LOCATION)
                .marker("on", LOCATION).marker("in", LOCATION).marker("under", LOCATION).marker("next to", LOCATION)
                .marker("in front of", LOCATION).marker("around", LOCATION);
        standardVerbs(b);
        return b.build();
    }

    private static void standardVerbs(Builder b) {
        b.verb(Verb.of("sit", Kind.COMMAND).particles("down").allows(LOCATION, TIME).build())
                .verb(Verb.of("lie", Kind.COMMAND).action("lie-down").particles("down").allows(LOCATION, TIME).build())
                .verb(Verb.of("stand", Kind.COMMAND).particles("up").allows(LOCATION, TIME).build())
                .verb(Verb.of("stop", Kind.COMMAND).allows(TIME).build())
                .verb(Verb.of("wait", Kind.COMMAND).allows(OBJECT, LOCATION, TIME).marker("for", OBJECT).build())
                .verb(Verb.of("come", Kind.COMMAND).particles("over", "back").allows(GOAL, SOURCE, TIME).build())
                .verb(Verb.of("go", Kind.COMMAND).requires(GOAL).allows(SOURCE, TIME).build())
                .verb(Verb.of("walk", Kind.COMMAND).allows(GOAL, SOURCE, TIME).build())
                .verb(Verb.of("move", Kind.COMMAND).allows(GOAL, SOURCE, TIME).build())
                .verb(Verb.of("turn", Kind.COMMAND).allows(GOAL, TIME).build())
                .verb(Verb.of("look", Kind.COMMAND).allows(GOAL, TIME).marker("at", GOAL).build())
                .verb(Verb.of("shake", Kind.COMMAND).action("shake-hands").particles("hands", "hand").particleRequired()
                        .allows(CO_AGENT, TIME).build())
                .verb(Verb.of("wave", Kind.COMMAND).allows(RECIPIENT, TIME).marker("at", RECIPIENT)
                        .marker("to", RECIPIENT).build())
                .verb(Verb.of("follow", Kind.COMMAND).requires(OBJECT).allows(TIME).build())
                .verb(Verb.of("greet", Kind.COMMAND).requires(OBJECT).allows(TIME).build())
                .verb(Verb.of("dance", Kind.COMMAND).allows(CO_AGENT, LOCATION, TIME).build())
                .verb(Verb.of("sing", Kind.COMMAND).allows(RECIPIENT, TIME).build())
                .verb(Verb.of("bark", Kind.COMMAND).allows(TIME).marker("at", GOAL).allows(GOAL).build())
                .verb(Verb.of("play", Kind.COMMAND).allows(CO_AGENT, INSTRUMENT, LOCATION, TIME).build())
                .verb(Verb.of("find", Kind.COMMAND).requires(OBJECT).allows(TIME).build())
                .verb(Verb.of("introduce", Kind.COMMAND).requires(OBJECT).allows(RECIPIENT, TIME)
                        .marker("to", RECIPIENT).build());
        for (String transfer : List.of("bring", "fetch", "get", "give", "hand", "take", "pass", "serve")) {
            b.verb(Verb.of(transfer, Kind.TRANSFER).action(transfer.equals("fetch") || transfer.equals("get")
                            ? "bring" : transfer)
                    .requires(OBJECT).allows(RECIPIENT, GOAL, SOURCE, QUANTITY, TIME).build());
        }
        for (String want : List.of("want", "like", "love", "have", "need", "prefer", "take", "get")) {
            b.want(Verb.of(want, Kind.WANT).action("want").requires(OBJECT).allows(RECIPIENT, QUANTITY, TIME).build());
        }
        for (String correct : List.of("meant", "said")) {
            b.want(Verb.of(correct, Kind.CORRECT).action("want").requires(OBJECT).allows(RECIPIENT, QUANTITY).build());
        }
    }

    /** Collects entries; later entries replace earlier ones of the same word. */
    public static final class Builder {
        private final Map<String, Noun> nouns;
        private final Map<String, Verb> verbs;
        private final Map<String, Case> markers;

        private Builder(Map<String, Noun> nouns, Map<String, Verb> verbs, Map<String, Case> markers) {
            this.nouns = new HashMap<>(nouns);
            this.verbs = new HashMap<>(verbs);
            this.markers = new HashMap<>(markers);
        }

        /** A noun: the word as said (lower case), its normalised value and class. */
        public Builder noun(String word, String value, SemanticClass semanticClass) {
            nouns.put(word, new Noun(value, semanticClass));
            return this;
        }

        /** A verb under its lemma, replacing any imperative use of the word. */
        public Builder verb(Verb verb) {
            verbs.put(verb.lemma(), verb);
            return this;
        }

        /**
         * A verb of wanting, said after "I" (want, like, have, meant); kept apart from the imperative verbs because
         * "I take tea" and "take the tea" mean different things.
         */
        public Builder want(Verb verb) {
            verbs.put("i:" + verb.lemma(), verb);
            return this;
        }

        /** A case-marking preposition (one or more words). */
        public Builder marker(String preposition, Case c) {
            markers.put(preposition, c);
            return this;
        }

        public Lexicon build() {
            return new Lexicon(nouns, verbs, markers);
        }
    }

    /** A verb used after "I" (want, like, have, meant): the speaker's own wish, not a command. */
    public Optional<Verb> firstPersonVerb(String word) {
        return Optional.ofNullable(verbs.get("i:" + word));
    }
}
