package org.kicnp.language;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** The sentence table {@code sentences.tsv}: every row is one test of the whole parser, compared case by case. */
class SentencesTest {
    private static final Pattern CASE = Pattern.compile("(\\w+)=(?:\"([^\"]*)\"|([^\\s:?\"]+))(?::([A-Z_]+))?(\\?)?");
    private static final Pattern EXPECT = Pattern.compile("^\\[expect (\\w+)]\\s*");
    private static final SentenceParser PARSER = SentenceParser.standard();

    /** One row: the sentence, what the dialogue expects, and the expected result (empty act = not understood). */
    record Row(int line, String sentence, Expectation expectation, String expected) {
        @Override public String toString() {
            return "line " + line + ": \"" + sentence + "\"" + (expectation == Expectation.NONE ? "" : " [" + expectation + "]")
                    + " -> " + expected;
        }
    }

    /** An expected filler: value, optional class, known flag. */
    record Expected(String value, Optional<SemanticClass> semanticClass, boolean known) {
    }

    static List<Row> rows() throws IOException {
        List<Row> rows = new ArrayList<>();
        try (var in = Objects.requireNonNull(SentencesTest.class.getResourceAsStream("sentences.tsv"), "sentences.tsv");
             var r = new BufferedReader(new InputStreamReader(in, UTF_8))) {
            String line;
            int n = 0;
            while ((line = r.readLine()) != null) {
                n++;
                if (line.isBlank() || line.startsWith("#")) {
                    continue;
                }
                String[] cols = line.split("\t");
                if (cols.length != 2) {
                    throw new IllegalStateException("sentences.tsv:" + n + " needs two TAB-separated columns: '" + line + "'.");
                }
                String sentence = cols[0];
                Expectation expectation = Expectation.NONE;
                Matcher m = EXPECT.matcher(sentence);
                if (m.find()) {
                    expectation = Expectation.valueOf(m.group(1));
                    sentence = sentence.substring(m.end());
                }
                rows.add(new Row(n, sentence.equals("<empty>") ? "" : sentence, expectation, cols[1].strip()));
            }
        }
        return rows;
    }

    @Test
    void table_hasEnoughSentences_andEnoughThatAreNotUnderstood() throws IOException {
        List<Row> rows = rows();
        assertThat(rows).hasSizeGreaterThanOrEqualTo(60);
        assertThat(rows).filteredOn(r -> r.expected().equals("NOT_UNDERSTOOD")).hasSizeGreaterThanOrEqualTo(10);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("rows")
    void sentence_parsesToTheExpectedCaseFrame(Row row) {
        ParseResult result = PARSER.parse(row.sentence(), row.expectation());
        if (row.expected().equals("NOT_UNDERSTOOD")) {
            assertThat(result).as(row.toString()).isInstanceOfSatisfying(ParseResult.NotUnderstood.class, n -> {
                assertThat(n.reply()).isEqualTo("Sorry, I didn't catch that. Could you say it again?");
                assertThat(n.reason()).isNotBlank();
            });
            return;
        }
        String[] head = row.expected().split("\\s+", 2);
        Act act = Act.valueOf(head[0]);
        String rest = head.length > 1 ? head[1] : "";
        boolean correction = rest.startsWith("correction");
        Map<Case, Expected> expected = expectedCases(rest.replaceFirst("^correction\\s*", ""), row);
        assertThat(result).as(row.toString()).isInstanceOf(ParseResult.Parsed.class);
        CaseFrame frame = ((ParseResult.Parsed) result).frame();
        assertThat(frame.act()).as(row + " act; got " + frame).isEqualTo(act);
        assertThat(frame.correction()).as(row + " correction; got " + frame).isEqualTo(correction);
        assertThat(frame.cases().keySet()).as(row + " cases; got " + frame)
                .containsExactlyInAnyOrderElementsOf(expected.keySet());
        expected.forEach((c, e) -> {
            Filler f = frame.cases().get(c);
            assertThat(f.value()).as(row + " value of " + c).isEqualTo(e.value());
            assertThat(f.known()).as(row + " known flag of " + c).isEqualTo(e.known());
            e.semanticClass().ifPresent(sc -> assertThat(f.semanticClass()).as(row + " class of " + c).isEqualTo(sc));
        });
        assertThat(frame.text()).isEqualTo(row.sentence().strip());
    }

    private static Map<Case, Expected> expectedCases(String spec, Row row) {
        Map<Case, Expected> out = new EnumMap<>(Case.class);
        Matcher m = CASE.matcher(spec);
        int at = 0;
        while (m.find()) {
            if (!spec.substring(at, m.start()).isBlank()) {
                throw new IllegalStateException("Cannot read '" + spec.substring(at, m.start()) + "' in " + row + ".");
            }
            at = m.end();
            Case c = Case.valueOf(m.group(1).toUpperCase(Locale.ROOT));
            String value = m.group(2) != null ? m.group(2) : m.group(3);
            Optional<SemanticClass> sc = Optional.ofNullable(m.group(4)).map(SemanticClass::valueOf);
            out.put(c, new Expected(value, sc, m.group(5) == null));
        }
        if (!spec.substring(at).isBlank()) {
            throw new IllegalStateException("Cannot read '" + spec.substring(at) + "' in " + row + ".");
        }
        return out;
    }
}
