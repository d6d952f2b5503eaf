package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

class ConditionParserTest {

    @ParameterizedTest
    @ValueSource(strings = {"", "COND_ANY", "any", "NULL", "  COND_ANY  "})
    void parse_anyForms_giveAny(String text) {
        assertThat(ConditionParser.parse(text)).isSameAs(Condition.ANY);
    }

    @Test
    void parse_comparisonAgainstConstant() {
        assertThat(ConditionParser.parse("== \"tea\""))
                .isEqualTo(new Condition.Compare(List.of(), Condition.Op.EQ, new Operand.Constant(Value.of("tea"))));
        assertThat(ConditionParser.parse(">= 2.5"))
                .isEqualTo(new Condition.Compare(List.of(), Condition.Op.GE, new Operand.Constant(Value.of(2.5))));
        assertThat(ConditionParser.parse("!= -3"))
                .isEqualTo(new Condition.Compare(List.of(), Condition.Op.NE, new Operand.Constant(Value.of(-3))));
    }

    @Test
    void parse_leftPathAndSlotPathOperand_formAJoin() {
        assertThat(ConditionParser.parse(".user == mUser"))
                .isEqualTo(new Condition.Compare(List.of("user"), Condition.Op.EQ, new Operand.Path(List.of("mUser"))));
        assertThat(ConditionParser.parse(".speaker.name = s.mUser.name"))
                .isEqualTo(new Condition.Compare(List.of("speaker", "name"), Condition.Op.EQ,
                        new Operand.Path(List.of("mUser", "name"))));
    }

    @Test
    void parse_rangeMembershipPatternFrameRefAndScript() {
        assertThat(ConditionParser.parse("between 1 and 5")).isInstanceOf(Condition.Between.class);
        assertThat(ConditionParser.parse(".drink in (\"tea\", 'coffee')"))
                .isEqualTo(new Condition.OneOf(List.of("drink"), List.of(
                        new Operand.Constant(Value.of("tea")), new Operand.Constant(Value.of("coffee")))));
        assertThat(ConditionParser.parse("matches \"K.*\"")).isEqualTo(new Condition.Matches(List.of(), "K.*"));
        assertThat(ConditionParser.parse("== @Kitchen"))
                .isEqualTo(new Condition.Compare(List.of(), Condition.Op.EQ, new Operand.Constant(Value.ref("Kitchen"))));
        assertThat(ConditionParser.parse("js: s.mUser.age > 3")).isEqualTo(new Condition.Script("s.mUser.age > 3"));
        assertThat(ConditionParser.parse(".ok == TRUE"))
                .isEqualTo(new Condition.Compare(List.of("ok"), Condition.Op.EQ, new Operand.Constant(Value.of(true))));
    }

    @Test
    void parse_typographicQuotesFromThePaper_areStrings() {
        assertThat(ConditionParser.parse("== \u201Ctea\u201D"))
                .isEqualTo(new Condition.Compare(List.of(), Condition.Op.EQ, new Operand.Constant(Value.of("tea"))));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "== \"tea\"", ".status != \"ended\"", "< 10", ".a.b >= mUser.age", "between 1 and 5.5",
        ".drink in (\"tea\", \"coffee\")", "matches \"K\\\\d+\"", "== @Kitchen", "js: s.x > 1", "COND_ANY"})
    void text_roundTripsThroughTheParser(String text) {
        Condition c = ConditionParser.parse(text);
        assertThat(ConditionParser.parse(c.text())).isEqualTo(c);
    }

    @Test
    void parse_errorsNameTheColumnAndWhatWasExpected() {
        assertThatThrownBy(() -> ConditionParser.parse("== \"tea"))
                .isInstanceOf(ConditionSyntaxException.class)
                .hasMessage("Condition '== \"tea' is not valid at character 8: expected a closing quote.");
        assertThatThrownBy(() -> ConditionParser.parse("~ 3"))
                .hasMessageContaining("at character 1: expected a comparison");
        assertThatThrownBy(() -> ConditionParser.parse("between 1 5"))
                .hasMessageContaining("expected 'and' after the lower bound");
        assertThatThrownBy(() -> ConditionParser.parse("matches \"[\""))
                .hasMessageContaining("is not a valid pattern");
        assertThatThrownBy(() -> ConditionParser.parse("== 1 2"))
                .hasMessageContaining("expected the end of the condition");
    }

    @Test
    void parse_whenANumberIsTooLarge_saysSoInsteadOfNotANumberOrInfinity() {
        assertThatThrownBy(() -> ConditionParser.parse("> 99999999999999999999"))
                .hasMessage("Condition '> 99999999999999999999' is not valid at character 3: expected a whole number from "
                        + "-9223372036854775808 to 9223372036854775807 (found '99999999999999999999').");
        assertThatThrownBy(() -> ConditionParser.parse("< 1e999"))
                .hasMessage("Condition '< 1e999' is not valid at character 3: expected a number up to about 1.8e308 "
                        + "(found '1e999').");
    }

    @Test
    void parse_whenPatternIsInvalid_saysWhyInOneSentence() {
        assertThatThrownBy(() -> ConditionParser.parse("matches \"[a-\""))
                .isInstanceOf(ConditionSyntaxException.class)
                .hasMessage("Condition 'matches \"[a-\"' is not valid at character 13: '[a-' is not a valid pattern: "
                        + "Illegal character range.");
    }
}
