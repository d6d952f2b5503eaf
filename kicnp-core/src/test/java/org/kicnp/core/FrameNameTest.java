package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

class FrameNameTest {

    @Test
    void nameFor_keepsLettersDigitsUnderscoresAndHyphens_andPutsOneUnderscoreForEachRunOfAnythingElse() {
        assertThat(Frame.nameFor("Ken")).isEqualTo("Ken");
        assertThat(Frame.nameFor("José O'Brien")).isEqualTo("José_O_Brien");
        assertThat(Frame.nameFor("Ken  Smith")).isEqualTo("Ken_Smith");
        assertThat(Frame.nameFor("Jean-Luc")).isEqualTo("Jean-Luc");
        assertThat(Frame.nameFor("太郎")).isEqualTo("太郎");
        assertThat(Frame.nameFor("Jose\u0301")).as("a combining accent is not a letter").isEqualTo("Jose_");
    }

    @Test
    void nameFor_startsWithAnUnderscore_whenTheTextDoesNotStartWithALetter() {
        assertThat(Frame.nameFor("\uD842\uDFB7野")).as("a letter beyond U+FFFF").isEqualTo("_野");
        assertThat(Frame.nameFor("2nd")).isEqualTo("_2nd");
        assertThat(Frame.nameFor("-x")).isEqualTo("_-x");
        assertThat(Frame.nameFor("")).isEqualTo("_");
        assertThat(Frame.nameFor("  ")).isEqualTo("_");
    }

    @Test
    void nameFor_alwaysGivesANameAFrameTakes() {
        for (String text : List.of("José O'Brien", "\uD842\uDFB7野", "2nd", "", "a&b<c>", "-", "O'", "\u0301x")) {
            String name = Frame.nameFor(text);
            assertThat(Frame.classFrame(name).build().name()).as(text).isEqualTo(name);
        }
    }

    @Test
    void isFrameName_takesAfterTheFirstCharacterEveryLetterOrDigitUnderscoreAndHyphen_andNothingElse() {
        for (int c = 0; c <= Character.MAX_VALUE; c++) {
            boolean expected = Character.isLetterOrDigit((char) c) || c == '_' || c == '-';
            assertThat(Names.isFrameName("a" + (char) c)).as("U+%04X", c).isEqualTo(expected);
        }
    }

    @Test
    void isSlotName_takesAfterTheFirstCharacterEveryLetterOrDigitUnderscoreAndDollar_andNothingElse() {
        for (int c = 0; c <= Character.MAX_VALUE; c++) {
            boolean expected = Character.isLetterOrDigit((char) c) || c == '_' || c == '$';
            assertThat(Names.isSlotName("a" + (char) c)).as("U+%04X", c).isEqualTo(expected);
        }
    }
}
