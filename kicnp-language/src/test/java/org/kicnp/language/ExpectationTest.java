package org.kicnp.language;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** What a robot's line leaves the dialogue expecting, and the relay subject that carries it to the parser. */
class ExpectationTest {
    @Test
    void after_aQuestionForANameOrADrink_expectsOne() {
        assertThat(Expectation.after("How are you! I have never seen you before. What is your name?"))
                .isEqualTo(Expectation.NAME);
        assertThat(Expectation.after("What do you want to drink? ")).isEqualTo(Expectation.DRINK);
    }

    @Test
    void after_aStatementOrAnotherQuestion_expectsNothing() {
        assertThat(Expectation.after("Hi, Ken. Nice to meet you. Welcome you to visit my room.")).isEqualTo(Expectation.NONE);
        assertThat(Expectation.after("I am sorry, we have no lemonade. We have tea and coffee.")).isEqualTo(Expectation.NONE);
        assertThat(Expectation.after("Shall we play?")).isEqualTo(Expectation.NONE);
    }

    @Test
    void subject_carriesTheExpectation_asTheParserAgentReadsIt() {
        assertThat(ParserAgent.subject(Expectation.NONE)).isEqualTo(ParserAgent.SUBJECT);
        assertThat(ParserAgent.subject(Expectation.NAME)).isEqualTo("utterance:name");
        assertThat(ParserAgent.subject(Expectation.DRINK)).isEqualTo("utterance:drink");
    }
}
