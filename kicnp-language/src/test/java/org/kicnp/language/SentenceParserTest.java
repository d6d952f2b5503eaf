package org.kicnp.language;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** What the sentence table does not show: the reasons given, extending the lexicon, and the tokenizer. */
class SentenceParserTest {
    private final SentenceParser parser = SentenceParser.standard();

    private String reason(String sentence) {
        return ((ParseResult.NotUnderstood) parser.parse(sentence)).reason();
    }

    @Test
    void notUnderstood_whenVerbTakesNoSuchCase_saysWhichAndQuotesTheWords() {
        assertThat(reason("AIBO, sit down to the door")).isEqualTo("'sit' takes no goal such as 'the door'.");
    }

    @Test
    void notUnderstood_whenVerbMissesARequiredCase_saysWhich() {
        assertThat(reason("Scout, go")).isEqualTo("'go' needs a goal.");
        assertThat(reason("Bring")).isEqualTo("'bring' needs an object.");
    }

    @Test
    void notUnderstood_forGibberish_quotesTheUnknownWord() {
        assertThat(reason("blorf zap")).isEqualTo(
                "The word 'blorf' is not in the lexicon, and no rule of the grammar reads 'blorf zap'.");
    }

    @Test
    void notUnderstood_whenAskingForSomethingNotToDrink_saysSo() {
        assertThat(reason("I want the door")).isEqualTo("'the door' is not something to drink.");
    }

    @Test
    void notUnderstood_whenTheNameGivenIsARobots_saysSo() {
        assertThat(reason("My name is Scout")).isEqualTo("'Scout' is a robot's name, not a person's.");
    }

    @Test
    void notUnderstood_whenTheSentenceIsLongerThanAnyoneSays_withoutQuotingIt() {
        String said = "Tea, please " + "blorf ".repeat(1_000);
        assertThat(reason(said)).isEqualTo("The sentence is " + said.strip().length() + " characters long; at most "
                + SentenceParser.MAX_LENGTH + " are read.");
    }

    @Test
    void extendedLexicon_knowsANewDrink_andANewVerb() {
        Lexicon lexicon = Lexicon.standard().toBuilder()
                .noun("lemonade", "lemonade", SemanticClass.DRINK)
                .verb(Verb.of("jump", Verb.Kind.COMMAND).allows(Case.GOAL).build())
                .build();
        SentenceParser extended = SentenceParser.with(lexicon);
        CaseFrame lemonade = ((ParseResult.Parsed) extended.parse("I'd like a lemonade")).frame();
        assertThat(lemonade.filler(Case.OBJECT)).get().extracting(Filler::known).isEqualTo(true);
        CaseFrame jump = ((ParseResult.Parsed) extended.parse("AIBO, jump onto the sofa")).frame();
        assertThat(jump.value(Case.ACTION)).contains("jump");
        assertThat(jump.value(Case.GOAL)).contains("sofa");
        assertThat(parser.parse("AIBO, jump onto the sofa")).isInstanceOf(ParseResult.NotUnderstood.class);
    }

    @Test
    void verb_requiringACaseItDoesNotAllow_isRefusedWithMessage() {
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> new Verb("go", "go", Verb.Kind.COMMAND,
                        java.util.Set.of(), false, java.util.Set.of(), java.util.Set.of(Case.GOAL), java.util.Map.of()))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("Verb 'go' requires cases it does not allow: [GOAL].");
    }

    @Test
    void tokenizer_expandsContractions_keepsCommas_separatesAtInnerStops_andDropsFinalPunctuation() {
        assertThat(new Tokenizer().tokenize("I'm Ken, it's me! Don't stop?")).extracting(Token::word)
                .containsExactly("i", "am", "ken", ",", "it", "is", "me", ",", "do", "not", "stop");
    }

    @Test
    void tokenizer_keepsTheSurfaceSpelling_forProperNames() {
        assertThat(new Tokenizer().tokenize("Call me McKenzie")).extracting(Token::surface)
                .containsExactly("Call", "me", "McKenzie");
    }

    @Test
    void tokenizer_readsCurlyApostrophes_andPossessives() {
        assertThat(new Tokenizer().tokenize("I\u2019d like Ken's tea")).extracting(Token::word)
                .containsExactly("i", "would", "like", "ken", "tea");
    }

    @Test
    void name_keepsAccentsTypedAsCombiningMarks_lettersBeyondTheBasicPlane_andVowelSigns() {
        assertThat(name("My name is Jose\u0301.")).isEqualTo("Jos\u00e9");
        assertThat(name("My name is \uD842\uDFB7\u91CE.")).isEqualTo("\uD842\uDFB7\u91CE"); // Yoshino, 𠮷 (U+20BB7)
        String priya = "\u092A\u094D\u0930\u093F\u092F\u093E"; // in Devanagari, with a virama and two vowel signs
        assertThat(name("My name is " + priya)).isEqualTo(priya);
    }

    private String name(String sentence) {
        return ((ParseResult.Parsed) parser.parse(sentence)).frame().value(Case.ATTRIBUTE).orElseThrow();
    }

    @Test
    void name_keepsTheSpeakersCapitals() {
        CaseFrame f = ((ParseResult.Parsed) parser.parse("Call me McKenzie")).frame();
        assertThat(f.value(Case.ATTRIBUTE)).contains("McKenzie");
    }
}
