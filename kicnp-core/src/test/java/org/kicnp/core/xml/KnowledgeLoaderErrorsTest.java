package org.kicnp.core.xml;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.kicnp.core.xml.LoaderErrorFiles.classFrame;
import static org.kicnp.core.xml.LoaderErrorFiles.errors;
import static org.kicnp.core.xml.LoaderErrorFiles.kb;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;

/** Loading XML that cannot be read as the paper's format: each error names its file, line, frame and slot. */
class KnowledgeLoaderErrorsTest {
    @TempDir Path dir;

    private Path file(String name, String xml) throws IOException {
        return LoaderErrorFiles.write(dir, name, xml);
    }

    @Test
    void load_whenParentMissingInAnotherFile_reportsFileLineAndColumnOfIsa() throws IOException {
        Path a = file("a.xml", kb(classFrame("Speech", null)));
        Path b = file("b.xml", kb(classFrame("Greeting", "Speach")));

        assertThat(errors(List.of(a, b))).containsExactly(
                b + ":4:5: Frame 'Greeting' is a kind of 'Speach', which is not defined.");
    }

    @Test
    void load_whenXmlMalformed_reportsWhereTheParserStopped() throws IOException {
        Path a = file("a.xml", "<KNOWLEDGEBASE>\n  <FRAME>\n    <NAME>X</NAM>\n  </FRAME>\n</KNOWLEDGEBASE>\n");

        List<String> errors = errors(List.of(a));

        assertThat(errors).hasSize(1);
        assertThat(errors.getFirst()).startsWith(a + ":3:").contains("The XML is not well-formed");
    }

    @Test
    void load_whenAByteIsNotUtf8_reportsItsLineAndColumnAndHowToFixIt() throws IOException {
        Path a = dir.resolve("latin1.xml");
        byte[] head = (kb(classFrame("Drink", null)).replace("</KNOWLEDGEBASE>\n", "")
                + "  <FRAME><NAME>Cafe</NAME><ISA>Drink</ISA><!-- caf").getBytes(StandardCharsets.US_ASCII);
        byte[] tail = " au lait --></FRAME>\n</KNOWLEDGEBASE>\n".getBytes(StandardCharsets.US_ASCII);
        byte[] bytes = new byte[head.length + 1 + tail.length];
        System.arraycopy(head, 0, bytes, 0, head.length);
        bytes[head.length] = (byte) 0xE9;
        System.arraycopy(tail, 0, bytes, head.length + 1, tail.length);
        Files.write(a, bytes);

        assertThat(errors(List.of(a))).containsExactly(a + ":6:51: The file is not valid UTF-8: byte 0xE9 here does "
                + "not make a UTF-8 character; save the file as UTF-8, or name its encoding in the XML declaration "
                + "(<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>).");
    }

    @Test
    void load_whenBooleanIsBad_reportsTheElement() throws IOException {
        Path a = file("a.xml", """
                <FRAME>
                  <NAME>X</NAME>
                  <ISINSTANCE>FALSE</ISINSTANCE>
                  <SLOTLIST>
                    <SLOT>
                      <NAME>s</NAME>
                      <TYPE>TYPE_INT</TYPE>
                      <REQUIRED>Maybe</REQUIRED>
                    </SLOT>
                  </SLOTLIST>
                </FRAME>
                """);

        assertThat(errors(List.of(a))).containsExactly(a + ":8:7: Slot 's' of frame 'X' has REQUIRED 'Maybe', "
                + "which is not a boolean; write TRUE or FALSE.");
    }

    @Test
    void load_whenValueAndDefaultBothGiven_reportsTheDefault() throws IOException {
        Path a = file("a.xml", """
                <FRAME>
                  <NAME>X</NAME>
                  <SLOTLIST>
                    <SLOT>
                      <NAME>s</NAME>
                      <TYPE>TYPE_INT</TYPE>
                      <VALUE>1</VALUE>
                      <DEFAULT>2</DEFAULT>
                    </SLOT>
                  </SLOTLIST>
                </FRAME>
                """);

        assertThat(errors(List.of(a))).containsExactly(a + ":8:7: Slot 's' of frame 'X' has both a VALUE and a "
                + "DEFAULT; the paper allows one or the other (Table 2).");
    }

    @Test
    void load_whenElementUnknown_reportsItAndGoesOn() throws IOException {
        Path a = file("a.xml", """
                <FRAME>
                  <NAME>X</NAME>
                  <ISINSTANCE>FALSE</ISINSTANCE>
                  <SLOTLIST>
                    <SLOT>
                      <NAME>s</NAME>
                      <TYPE>TYPE_INT</TYPE>
                      <REQIURED>TRUE</REQIURED>
                      <VALUE>one</VALUE>
                    </SLOT>
                  </SLOTLIST>
                  <COLOUR>red</COLOUR>
                </FRAME>
                """);

        List<String> errors = errors(List.of(a));

        assertThat(errors).hasSize(3);
        assertThat(errors.get(0)).startsWith(a + ":8:7: Unknown element 'REQIURED' in SLOT; expected NAME, TYPE");
        assertThat(errors.get(1)).isEqualTo(a + ":9:7: Slot 's' of frame 'X' has a VALUE that does not fit its "
                + "type TYPE_INT: 'one' is not an integer.");
        assertThat(errors.get(2)).startsWith(a + ":12:3: Unknown element 'COLOUR' in FRAME; expected NAME, ISA");
    }

    /** The editor's import shows each error at its frame and slot: mistakes in the structure concern one too. */
    @Test
    void parseText_whenElementsAreUnknownRepeatedOrHaveAttributes_namesTheFrameAndSlotTheyAreIn() {
        String xml = """
                <KNOWLEDGEBASE>
                  <FRAME>
                    <NAME>X</NAME>
                    <SLOTLIST>
                      <SLOT>
                        <REQIURED>TRUE</REQIURED>
                        <NAME>s</NAME>
                        <TYPE lang="en">TYPE_INT</TYPE>
                      </SLOT>
                      <SLOT><NAME>t</NAME><TYPE>TYPE_INT</TYPE>stray</SLOT>
                    </SLOTLIST>
                    <ISA>A</ISA>
                    <ISA>B</ISA>
                  </FRAME>
                  <FRAME><COLOUR>red</COLOUR></FRAME>
                </KNOWLEDGEBASE>
                """;

        KnowledgeXmlException e = catchThrowableOfType(KnowledgeXmlException.class,
                () -> KnowledgeLoader.parseText(xml, "editor", KnowledgeBase.create()));

        assertThat(e.errors()).extracting(LoadError::line, err -> err.frame().orElse("-"), err -> err.slot().orElse("-"))
                .containsExactly(
                        org.assertj.core.groups.Tuple.tuple(6, "X", "s"),
                        org.assertj.core.groups.Tuple.tuple(8, "X", "s"),
                        org.assertj.core.groups.Tuple.tuple(10, "X", "t"),
                        org.assertj.core.groups.Tuple.tuple(13, "X", "-"),
                        org.assertj.core.groups.Tuple.tuple(15, "-", "-"),
                        org.assertj.core.groups.Tuple.tuple(15, "-", "-"));
    }

    @Test
    void load_whenAClassHasAnError_itsInstancesStillTakeTheSlotTypesItDeclares() throws IOException {
        Path a = file("a.xml", """
                <KNOWLEDGEBASE>
                  <FRAME>
                    <NAME>Lamp</NAME>
                    <PRIORITY>high</PRIORITY>
                    <SLOTLIST><SLOT><NAME>watts</NAME><TYPE>TYPE_INT</TYPE></SLOT></SLOTLIST>
                  </FRAME>
                  <FRAME>
                    <NAME>lamp1</NAME><ISA>Lamp</ISA><ISINSTANCE>TRUE</ISINSTANCE>
                    <SLOTLIST><SLOT><NAME>watts</NAME><VALUE>40</VALUE></SLOT></SLOTLIST>
                  </FRAME>
                </KNOWLEDGEBASE>
                """);

        // only the class's own error: not also "no frame above it declares a slot 'watts'" for the instance
        assertThat(errors(List.of(a))).singleElement().asString().startsWith(a + ":4:5: The PRIORITY of frame 'Lamp'");
    }

    @Test
    void load_whenSomeFramesHaveXmlErrors_stillReportsTheFrameModelProblemsOfTheOthers() throws IOException {
        Path a = file("a.xml", """
                <KNOWLEDGEBASE>
                  <FRAME>
                    <NAME>Cup</NAME><ISINSTANCE>FALSE</ISINSTANCE>
                    <SLOTLIST><SLOT><NAME>full</NAME><TYPE>TYPE_BOOL</TYPE><REQUIRED>Maybe</REQUIRED></SLOT></SLOTLIST>
                  </FRAME>
                  <FRAME><NAME>Greeting</NAME><ISA>Speach</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                </KNOWLEDGEBASE>
                """);
        Path b = file("b.xml", kb(
                "  <FRAME>\n    <NAME>Serve</NAME>\n    <SLOTLIST><SLOT><NAME>mUser</NAME><TYPE>TYPE_INSTANCE</TYPE>"
                        + "<ARGUMENT>Usr</ARGUMENT></SLOT></SLOTLIST>\n  </FRAME>\n"));
        KnowledgeBase kb = KnowledgeBase.create();

        KnowledgeXmlException e = catchThrowableOfType(KnowledgeXmlException.class,
                () -> KnowledgeLoader.load(kb, List.of(a, b)));

        // one round: the XML error and both frame-model problems, in document order
        assertThat(e.errors()).extracting(LoadError::format).containsExactly(
                a + ":4:60: Slot 'full' of frame 'Cup' has REQUIRED 'Maybe', which is not a boolean; write TRUE or FALSE.",
                a + ":6:31: Frame 'Greeting' is a kind of 'Speach', which is not defined.",
                b + ":4:15: Slot 'mUser' of frame 'Serve' names class 'Usr' as its ARGUMENT, which is not defined.");
        assertThat(e.errors().get(1).frame()).contains("Greeting");
        assertThat(e.errors().get(2).slot()).contains("mUser");
        assertThat(kb.size()).isZero();
        assertThat(kb.version()).isZero();
    }

    @Test
    void load_whenAFrameHasXmlErrors_reportsNothingThatOnlyFollowsFromIt() throws IOException {
        Path a = file("a.xml", """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Mug</NAME><ISINSTANCE>perhaps</ISINSTANCE>
                    <SLOTLIST><SLOT><NAME>owner</NAME><TYPE>TYPE_STR</TYPE></SLOT></SLOTLIST>
                  </FRAME>
                  <FRAME><NAME>mug1</NAME><ISA>Mug</ISA><ISINSTANCE>TRUE</ISINSTANCE>
                    <SLOTLIST><SLOT><NAME>owner</NAME><TYPE>TYPE_STR</TYPE><VALUE>ann</VALUE></SLOT></SLOTLIST>
                  </FRAME>
                  <FRAME><NAME>Shelf</NAME><ISINSTANCE>FALSE</ISINSTANCE><HASPART><PART>Mug</PART></HASPART>
                    <SLOTLIST>
                      <SLOT><NAME>holds</NAME><TYPE>TYPE_INSTANCE</TYPE><ARGUMENT>Mug</ARGUMENT><VALUE>mug1</VALUE></SLOT>
                      <SLOT><NAME>next</NAME><TYPE>TYPE_STR</TYPE><FRAMERELATED>Mug</FRAMERELATED></SLOT>
                    </SLOTLIST>
                  </FRAME>
                  <FRAME><NAME>Tray</NAME><ISINSTANCE>FALSE</ISINSTANCE>
                    <SLOTLIST>
                      <SLOT><NAME>cup</NAME><TYPE>TYPE_INSTANCE</TYPE><ARGUMNT>Mug</ARGUMNT></SLOT>
                    </SLOTLIST>
                  </FRAME>
                  <FRAME><NAME>Robot</NAME><ISA>Machine</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                </KNOWLEDGEBASE>
                """);

        List<String> errors = errors(List.of(a));

        // not "mug1 is a kind of 'Mug', which is not defined", "Shelf has part 'Mug'", "ARGUMENT 'Mug' ... not
        // defined", "names as frame-related ... 'Mug'", nor Tray's "holds an instance but has no ARGUMENT" (its ARGUMENT is the misspelt element); the
        // unrelated unknown parent of Robot is reported in the same round
        assertThat(errors).hasSize(3);
        assertThat(errors.get(0)).isEqualTo(a + ":2:26: Frame 'Mug' has ISINSTANCE 'perhaps', which is not a boolean; "
                + "write TRUE or FALSE.");
        assertThat(errors.get(1)).startsWith(a + ":16:55: Unknown element 'ARGUMNT' in SLOT;");
        assertThat(errors.get(2)).isEqualTo(a + ":19:28: Frame 'Robot' is a kind of 'Machine', which is not defined.");
    }

    @Test
    void load_whenAFrameIsPutInsideAnother_doesNotCallTheFramesThatNameItUndefined() throws IOException {
        Path a = file("a.xml", """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Machine</NAME>
                  <FRAME><NAME>Robot</NAME><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                  </FRAME>
                  <FRAME><NAME>Scout</NAME><ISA>Robot</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                </KNOWLEDGEBASE>
                """);

        // Robot was skipped, never read: "Scout is a kind of 'Robot', which is not defined" would send the user
        // looking for a frame that is there
        assertThat(errors(List.of(a))).singleElement().asString()
                .startsWith(a + ":3:3: Unknown element 'FRAME' in FRAME;");
    }

    @Test
    void load_whenAListedDescendantHasXmlErrors_doesNotAlsoCallTheListWrong() throws IOException {
        Path a = file("a.xml", """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Robot</NAME><DESCENDANTS><FRAME>Scout</FRAME><FRAME>Pino</FRAME></DESCENDANTS></FRAME>
                  <FRAME><NAME>Scout</NAME><ISA>Robot</ISA><ISINSTANCE>maybe</ISINSTANCE></FRAME>
                  <FRAME><NAME>Pino</NAME><ISA>Robot</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                  <FRAME><NAME>Aibo</NAME><DESCENDANTS><FRAME>Pino</FRAME></DESCENDANTS></FRAME>
                </KNOWLEDGEBASE>
                """);

        assertThat(errors(List.of(a))).containsExactly(
                a + ":3:44: Frame 'Scout' has ISINSTANCE 'maybe', which is not a boolean; write TRUE or FALSE.",
                a + ":5:27: Frame 'Aibo' lists DESCENDANTS 'Pino', but the frames that are a kind of it are none; "
                        + "descendants are derived from ISA, so list them exactly or leave DESCENDANTS empty.");
    }

    /**
     * Woodstox reports a mistake inside text that it has begun to read (a script's bare {@code &&}, an undeclared
     * entity after a first character, text over the size limit) only when the text is asked for, as an unchecked
     * exception; that used to escape the loader as a WstxLazyException without file or line, and the knowledge
     * base must be left as it was.
     */
    @Test
    void load_whenTextHasABareAmpersandOrUnknownEntityPastItsStart_reportsWhereAsMalformedXml() throws IOException {
        Path a = file("a.xml", """
                <FRAME>
                  <NAME>Greeting</NAME>
                  <SLOTLIST>
                    <SLOT>
                      <NAME>onInstantiate</NAME>
                      <TYPE>TYPE_STR</TYPE>
                      <VALUE>if (s.a && s.b) { sendmsg(s.mMouth, "hi"); }</VALUE>
                    </SLOT>
                  </SLOTLIST>
                </FRAME>
                """);
        Path b = file("b.xml", "<FRAME><NAME>Robot&nbsp;1</NAME></FRAME>\n");
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("Speech").build());

        KnowledgeXmlException e = catchThrowableOfType(KnowledgeXmlException.class,
                () -> KnowledgeLoader.load(kb, List.of(a, b)));

        assertThat(e).as("load should fail with the loader's own exception").isNotNull();
        assertThat(e.errors()).map(LoadError::format).containsExactly(
                a + ":7:23: The XML is not well-formed: Unexpected character '&' (code 38) (expected a name start "
                        + "character).",
                b + ":1:24: The XML is not well-formed: Undeclared general entity \"nbsp\".");
        assertThat(kb.size()).isEqualTo(1);
    }

    /** Malformed XML stops the reading, but the frame and slot being read when it stopped are known: the editor shows them. */
    @Test
    void parseText_whenXmlIsMalformedInsideASlot_namesTheFrameAndSlotBeingRead() {
        String xml = """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Done</NAME></FRAME>
                  <FRAME>
                    <NAME>Greeting</NAME>
                    <SLOTLIST>
                      <SLOT><NAME>mUser</NAME><TYPE>TYPE_STR</TYPE></SLOT>
                      <SLOT>
                        <NAME>onInstantiate</NAME>
                        <VALUE>if (s.a && s.b) { }</VALUE>
                      </SLOT>
                    </SLOTLIST>
                  </FRAME>
                </KNOWLEDGEBASE>
                """;

        KnowledgeXmlException e = catchThrowableOfType(KnowledgeXmlException.class,
                () -> KnowledgeLoader.parseText(xml, "editor", KnowledgeBase.create()));

        assertThat(e.errors()).singleElement().satisfies(err -> {
            assertThat(err.line()).isEqualTo(9);
            assertThat(err.frame()).contains("Greeting");
            assertThat(err.slot()).contains("onInstantiate");
        });
    }

    @Test
    void parseText_whenOneTextIsLargerThanTheLimit_reportsTheLimitWithItsPlace() {
        String xml = "<FRAME><NAME>X</NAME><SLOTLIST><SLOT><NAME>s</NAME><TYPE>TYPE_STR</TYPE>\n<VALUE>"
                + "ab".repeat(SecureXml.MAX_TEXT) + "</VALUE></SLOT></SLOTLIST></FRAME>";

        assertThatThrownBy(() -> KnowledgeLoader.parseText(xml, "net", KnowledgeBase.create()))
                .isInstanceOf(KnowledgeXmlException.class)
                .hasMessageStartingWith("net:2:")
                .hasMessageContaining("The XML is not well-formed: Text size limit (4194304) exceeded");
    }

    @Test
    void load_whenAFileIsNotWellFormed_reportsOnlyTheXmlErrors() throws IOException {
        Path a = file("a.xml", "<KNOWLEDGEBASE>\n  <FRAME>\n    <NAME>Machine</NAM>\n  </FRAME>\n</KNOWLEDGEBASE>\n");
        Path b = file("b.xml", kb(classFrame("Robot", "Machine")));

        List<String> errors = errors(List.of(a, b));

        // frames after the place the parser stopped were never read: "Machine is not defined" would be wrong
        assertThat(errors).singleElement().asString().startsWith(a + ":3:").contains("not well-formed");
    }

    @Test
    void load_whenNumbersAreTooLarge_saysSoInsteadOfCallingThemNotNumbersOrMakingThemInfinite() throws IOException {
        Path a = file("a.xml", """
                <FRAME>
                  <NAME>X</NAME>
                  <PRIORITY>99999999999</PRIORITY>
                  <SLOTLIST>
                    <SLOT><NAME>count</NAME><TYPE>TYPE_INT</TYPE><VALUE>99999999999999999999</VALUE></SLOT>
                    <SLOT><NAME>range</NAME><TYPE>TYPE_FLOAT</TYPE><VALUE>1e999</VALUE></SLOT>
                    <SLOT><NAME>limit</NAME><TYPE>TYPE_FLOAT</TYPE><VALUE>-Infinity</VALUE></SLOT>
                  </SLOTLIST>
                </FRAME>
                """);

        assertThat(errors(List.of(a))).containsExactly(
                a + ":3:3: The PRIORITY of frame 'X' is '99999999999', which is outside the range of a priority "
                        + "(-2147483648 to 2147483647).",
                a + ":5:50: Slot 'count' of frame 'X' has a VALUE that does not fit its type TYPE_INT: "
                        + "'99999999999999999999' is too large for an integer: TYPE_INT holds whole numbers from "
                        + "-9223372036854775808 to 9223372036854775807.",
                a + ":6:52: Slot 'range' of frame 'X' has a VALUE that does not fit its type TYPE_FLOAT: '1e999' is "
                        + "too large for a float: TYPE_FLOAT holds numbers up to about 1.8e308 (write Infinity if "
                        + "that is what you mean).");
    }

    /** NaN is no number: it equals nothing, orders against nothing and has no JSON form for the wire or the editor. */
    @Test
    void load_whenAFloatIsNaN_rejectsItNamingTheFrameAndSlotWhereverItIsWritten() throws IOException {
        Path a = file("a.xml", """
                <FRAME>
                  <NAME>X</NAME>
                  <SLOTLIST>
                    <SLOT><NAME>ratio</NAME><TYPE>TYPE_FLOAT</TYPE><VALUE>NaN</VALUE></SLOT>
                    <SLOT><NAME>gain</NAME><TYPE>TYPE_FLOAT</TYPE><DEFAULT> -NaN </DEFAULT></SLOT>
                    <SLOT><NAME>face</NAME><TYPE>TYPE_LIST</TYPE><ARGUMENT>TYPE_FLOAT</ARGUMENT>
                      <VALUE><ITEM>1.5</ITEM><ITEM>NaN</ITEM></VALUE></SLOT>
                    <SLOT><NAME>limit</NAME><TYPE>TYPE_FLOAT</TYPE><VALUE>Infinity</VALUE></SLOT>
                  </SLOTLIST>
                </FRAME>
                """);

        assertThat(errors(List.of(a))).containsExactly(
                a + ":4:52: Slot 'ratio' of frame 'X' has a VALUE that does not fit its type TYPE_FLOAT: 'NaN' is not "
                        + "a number: TYPE_FLOAT holds numbers (and Infinity or -Infinity), not NaN.",
                a + ":5:51: Slot 'gain' of frame 'X' has a DEFAULT that does not fit its type TYPE_FLOAT: '-NaN' is "
                        + "not a number: TYPE_FLOAT holds numbers (and Infinity or -Infinity), not NaN.",
                a + ":7:7: Slot 'face' of frame 'X' has a VALUE that does not fit its type TYPE_LIST: 'NaN' is not a "
                        + "number: TYPE_FLOAT holds numbers (and Infinity or -Infinity), not NaN.");
    }

    @Test
    void load_whenTypeUnknown_reportsTheTypeElement() throws IOException {
        Path a = file("a.xml", """
                <FRAME>
                  <NAME>X</NAME>
                  <SLOTLIST>
                    <SLOT>
                      <NAME>s</NAME>
                      <TYPE>TYPE_COLOUR</TYPE>
                    </SLOT>
                  </SLOTLIST>
                </FRAME>
                """);

        assertThat(errors(List.of(a))).containsExactly(a + ":6:7: Slot 's' of frame 'X' has TYPE 'TYPE_COLOUR', "
                + "which is not a data type; use TYPE_INSTANCE, TYPE_STR, TYPE_INT, TYPE_FLOAT, TYPE_BOOL, TYPE_FRAME "
                + "or TYPE_LIST.");
    }

    @Test
    void load_whenConditionHasSyntaxError_pointsIntoTheCondition() throws IOException {
        Path a = file("a.xml", """
                <FRAME>
                  <NAME>X</NAME>
                  <SLOTLIST>
                    <SLOT>
                      <NAME>s</NAME>
                      <TYPE>TYPE_INT</TYPE>
                      <CONDITION>between 1 or 5</CONDITION>
                    </SLOT>
                  </SLOTLIST>
                </FRAME>
                """);

        // "<CONDITION>" starts at column 7, its text at column 18; "or" is character 11 of the text.
        assertThat(errors(List.of(a))).containsExactly(a + ":7:28: Slot 's' of frame 'X': Condition 'between 1 or 5' "
                + "is not valid at character 11: expected 'and' after the lower bound.");
    }
}
