package org.kicnp.core.xml;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kicnp.core.ConditionParser;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.Provenance;
import org.kicnp.core.Relation;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

class KnowledgeXmlWriterTest {
    @TempDir Path dir;

    /** Frames that use every item and facet the format has, with text that needs escaping or CDATA. */
    static List<Frame> everything() {
        Frame root = Frame.classFrame("Machine").build();
        Frame robot = Frame.classFrame("Robot").parent("Machine")
                .part("Arm").part("Head")
                .linkTo(Relation.Coordination.SYNCHRONIZATION, "Head")
                .linkTo(new Relation.Named("guards <&> \u00FC"), "Arm")
                .linkFrom(Relation.Coordination.RESTRICTION, "Machine")
                .linkFrom(Relation.Coordination.SUCCESSION, "Head")
                .priority(-7)
                .slot(Slot.builder("name", DataType.STRING).required(true).shared(false).unique(true)
                        .role("who it is").from("agent <robovie> & co").condition(ConditionParser.parse("matches \"R.*\""))
                        .build())
                .slot(Slot.builder("speed", DataType.FLOAT).defaultValue(Value.of(1.5))
                        .condition(ConditionParser.parse("between 0 and 2.5")).build())
                .slot(Slot.builder("count", DataType.INTEGER).value(Value.of(-42L))
                        .condition(ConditionParser.parse(">= -100")).reactive(false).build())
                .slot(Slot.builder("on", DataType.BOOLEAN).value(Value.of(true)).build())
                .slot(Slot.builder("drink", DataType.STRING).value(Value.of("  tea with \"milk\" ]]> & <sugar>  "))
                        .condition(ConditionParser.parse("in (\"tea\", \"coffee\", 'it\\'s')")).build())
                .slot(Slot.builder("crlf", DataType.STRING).value(Value.of("line one\r\nline two\rthree")).build())
                .slot(Slot.builder("scores", DataType.LIST).argument("TYPE_INT")
                        .value(new Value.Lst(List.of(Value.of(1L), Value.of(2L), Value.of(3L)))).build())
                .slot(Slot.builder("tags", DataType.LIST)
                        .value(new Value.Lst(List.of(Value.of("a b"), Value.of(""), Value.of("<x>")))).build())
                .slot(Slot.builder("poses", DataType.LIST).value(new Value.Lst(List.of(Value.of("wave"),
                        new Value.Lst(List.of(Value.of("1"), new Value.Lst(List.of(Value.of("2"))))),
                        new Value.Lst(List.of()), Value.of("[]"))))
                        .build())
                .slot(Slot.builder("empty", DataType.LIST).argument("TYPE_FLOAT").value(new Value.Lst(List.of())).build())
                .slot(Slot.builder("friends", DataType.LIST).argument("Machine")
                        .defaultValue(new Value.Lst(List.of(Value.ref("Arm"), Value.ref("Head")))).build())
                .slot(Slot.builder("owner", DataType.FRAME).argument("Machine").value(Value.ref("Head"))
                        .frameRelated("Arm").frameListRelated(List.of("Arm", "Head")).build())
                .slot(Slot.builder("watch", DataType.STRING)
                        .condition(ConditionParser.parse("js: s.count < 3 && s.on"))
                        .onNeeded("return 'x';")
                        .onAdded("if (a < b && c) {\n  sendmsg(s.mMouth, \"hi ]]> there\");\n}\n")
                        .onRemoved("log('gone')").build())
                .slot(Slot.builder("path", DataType.INSTANCE).argument("Machine")
                        .condition(ConditionParser.parse(".name == owner.name")).build())
                .build();
        Frame arm = Frame.classFrame("Arm").parent("Machine").build();
        Frame head = Frame.classFrame("Head").parent("Machine").build();
        Frame learned = Frame.instance("user7", "Robot").provenance(Provenance.LEARNED)
                .slot(Slot.ofValue("name", DataType.STRING, Value.of("Taro"))).build();
        Frame runtime = Frame.instance("stimulus1", "Robot").provenance(Provenance.RUNTIME).build();
        return List.of(root, robot, arm, head, learned, runtime);
    }

    private static String save(List<Frame> frames) {
        StringWriter out = new StringWriter();
        KnowledgeXmlWriter.write(frames, out);
        return out.toString();
    }

    @Test
    void write_thenParse_givesEqualFramesForEveryFacet() {
        List<Frame> frames = everything().subList(0, 5);

        List<Frame> back = KnowledgeLoader.parseText(save(frames), "saved", KnowledgeBase.create()).stream()
                .map(SourcedFrame::frame).toList();

        assertThat(back).isEqualTo(frames);
        assertThat(back.get(4).learned()).isTrue();
    }

    @Test
    void write_runtimeFrame_isWrittenLikeADeclaredOne() {
        Frame runtime = everything().get(5);

        Frame back = KnowledgeLoader.parseText(KnowledgeXmlWriter.toXml(runtime), "x", KnowledgeBase.create())
                .getFirst().frame();

        assertThat(back.provenance()).isEqualTo(Provenance.DECLARED);
        assertThat(back).isEqualTo(runtime.toBuilder().provenance(Provenance.DECLARED).build());
    }

    @Test
    void parse_runtimeElement_marksTheFrameRuntime() {
        String xml = "<FRAME><NAME>s1</NAME><ISA>X</ISA><ISINSTANCE>TRUE</ISINSTANCE><RUNTIME>TRUE</RUNTIME></FRAME>";

        Frame f = KnowledgeLoader.parseText(xml, "x", KnowledgeBase.create()).getFirst().frame();

        assertThat(f.provenance()).isEqualTo(Provenance.RUNTIME);
    }

    @Test
    void write_twice_isByteIdentical() throws Exception {
        Path a = dir.resolve("a.xml");
        Path b = dir.resolve("b.xml");

        KnowledgeXmlWriter.write(everything(), a);
        KnowledgeXmlWriter.write(everything(), b);

        assertThat(Files.readAllBytes(a)).isEqualTo(Files.readAllBytes(b));
        assertThat(Files.readString(a, StandardCharsets.UTF_8)).isEqualTo(save(everything()));
    }

    @Test
    void write_usesThePapersLayout() {
        Frame f = Frame.classFrame("Greeting").parent("Speech")
                .slot(Slot.builder("mUser", DataType.INSTANCE).argument("KnownUser").required(true).unique(true).build())
                .slot(Slot.builder("onInstantiate", DataType.STRING).value(Value.of("Sendmsg(s.mMouth, \u201CHi!\u201D);"))
                        .unique(true).build())
                .build();

        assertThat(KnowledgeXmlWriter.toXml(f)).isEqualTo("""
                <?xml version="1.0" encoding="UTF-8"?>
                <FRAME>
                  <NAME>Greeting</NAME>
                  <ISA>Speech</ISA>
                  <ISINSTANCE>FALSE</ISINSTANCE>
                  <SLOTLIST>
                    <SLOT>
                      <NAME>mUser</NAME>
                      <TYPE>TYPE_INSTANCE</TYPE>
                      <ARGUMENT>KnownUser</ARGUMENT>
                      <REQUIRED>TRUE</REQUIRED>
                      <SHARED>TRUE</SHARED>
                      <UNIQUE>TRUE</UNIQUE>
                    </SLOT>
                    <SLOT>
                      <NAME>onInstantiate</NAME>
                      <TYPE>TYPE_STR</TYPE>
                      <VALUE>Sendmsg(s.mMouth, \u201CHi!\u201D);</VALUE>
                      <REQUIRED>FALSE</REQUIRED>
                      <SHARED>TRUE</SHARED>
                      <UNIQUE>TRUE</UNIQUE>
                    </SLOT>
                  </SLOTLIST>
                </FRAME>
                """);
    }

    @Test
    void write_instanceSlots_writeFlagsOnlyWhenNotDefaultAndReadBackEqual() {
        Frame f = Frame.instance("user1", "NewUser")
                .slot(Slot.ofValue("name", DataType.STRING, Value.of("Kim")))
                .slot(Slot.builder("age", DataType.INTEGER).value(Value.of(7L)).required(true).shared(false)
                        .unique(true).build())
                .build();

        String xml = KnowledgeXmlWriter.toXml(f);

        assertThat(xml).contains("""
                    <SLOT>
                      <NAME>name</NAME>
                      <TYPE>TYPE_STR</TYPE>
                      <VALUE>Kim</VALUE>
                    </SLOT>
                """).contains("""
                      <VALUE>7</VALUE>
                      <REQUIRED>TRUE</REQUIRED>
                      <SHARED>FALSE</SHARED>
                      <UNIQUE>TRUE</UNIQUE>
                """);
        assertThat(KnowledgeLoader.parseText(xml, "test", KnowledgeBase.create()))
                .extracting(SourcedFrame::frame).containsExactly(f);
    }

    @Test
    void write_scriptWithMarkup_usesCdataAndSplitsItsEnd() {
        Frame f = Frame.classFrame("B").slot(Slot.builder("s", DataType.STRING).onAdded("if (a < b) x(\"]]>\");\n")
                .build()).build();

        assertThat(KnowledgeXmlWriter.toXml(f))
                .contains("<ONADDED><![CDATA[if (a < b) x(\"]]]]><![CDATA[>\");\n]]></ONADDED>");
    }

    @Test
    void toXml_thenParseText_givesTheFrameBack() {
        Frame robot = everything().get(1);

        List<SourcedFrame> back = KnowledgeLoader.parseText(KnowledgeXmlWriter.toXml(robot), "editor",
                KnowledgeBase.create());

        assertThat(back).singleElement().satisfies(s -> {
            assertThat(s.frame()).isEqualTo(robot);
            assertThat(s.location()).isEqualTo(new SourceLocation("editor", 2, 1));
        });
    }

    @Test
    void write_whenTextHasACharacterXmlCannotHold_saysWhich() {
        Frame f = Frame.classFrame("B").slot(Slot.ofValue("s", DataType.STRING, Value.of("bell\u0007"))).build();

        assertThatThrownBy(() -> KnowledgeXmlWriter.toXml(f))
                .isInstanceOf(KnowledgeException.class)
                .hasMessage("The slot 's' of frame 'B' holds the character U+0007, which XML 1.0 cannot represent.");
    }

    /** The reader refuses one element's text over its limit, so writing it would give a file that cannot be loaded. */
    @Test
    void write_whenATextIsLongerThanTheReaderAccepts_refusesItInsteadOfWritingAFileThatCannotBeLoaded() {
        Frame f = Frame.classFrame("B").slot(Slot.ofValue("log", DataType.STRING, Value.of("x".repeat(SecureXml.MAX_TEXT
                + 1)))).build();

        assertThatThrownBy(() -> KnowledgeXmlWriter.toXml(f))
                .isInstanceOf(KnowledgeException.class)
                .hasMessage("The slot 'log' of frame 'B' holds 4194305 characters of text, more than the 4194304 a "
                        + "knowledge file may hold in one element.");
        assertThat(KnowledgeXmlWriter.toXml(Frame.classFrame("B").slot(Slot.ofValue("log", DataType.STRING,
                Value.of("x".repeat(SecureXml.MAX_TEXT)))).build())).hasSizeGreaterThan(SecureXml.MAX_TEXT);
    }

    @Test
    void parse_whenATextSplitByCommentsIsLongerThanTheLimit_reportsTheElement() {
        String half = "x".repeat(SecureXml.MAX_TEXT / 2 + 1);
        String xml = "<FRAME><NAME>B</NAME><SLOTLIST><SLOT><NAME>log</NAME><TYPE>TYPE_STR</TYPE>\n<VALUE>" + half
                + "<!-- -->" + half + "</VALUE></SLOT></SLOTLIST></FRAME>";

        assertThatThrownBy(() -> KnowledgeLoader.parseText(xml, "x", KnowledgeBase.create()))
                .isInstanceOf(KnowledgeXmlException.class)
                .hasMessage("x:2:1: Element VALUE holds 4194306 characters of text, more than the 4194304 a knowledge "
                        + "file may hold in one element.");
    }

    @Test
    void loadSaveLoad_ofTheScenario_givesEqualFramesAndIdenticalBytes() throws Exception {
        KnowledgeBase first = KnowledgeBase.create();
        KnowledgeLoader.load(first, List.of(ScenarioFilesTest.TABLE5));
        Path saved = dir.resolve("saved.xml");
        KnowledgeXmlWriter.write(first.frames(), saved);

        KnowledgeBase second = KnowledgeBase.create();
        KnowledgeLoader.load(second, List.of(saved));
        Path again = dir.resolve("again.xml");
        KnowledgeXmlWriter.write(second.frames(), again);

        assertThat(second.frames()).isEqualTo(first.frames());
        assertThat(Files.readAllBytes(again)).isEqualTo(Files.readAllBytes(saved));
    }

    @Test
    void listsInsideLists_areWrittenAsItemsInsideItems_andReadBackAsTheyWere() {
        // A face_seen signal's values: a name, a face descriptor, the empty list, and the text "[]" beside it.
        Value nested = new Value.Lst(List.of(Value.of("unknown"),
                new Value.Lst(List.of(Value.of("0.1"), Value.of("0.2"), new Value.Lst(List.of(Value.of("x"))))),
                new Value.Lst(List.of()), Value.of("[]"), Value.of(" [] "), Value.of("")));
        Frame f = Frame.instance("signal_robovie_face_seen", "SensorSignal").provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("values", DataType.LIST, nested)).build();

        String xml = KnowledgeXmlWriter.toXml(f);
        assertThat(xml).contains("<ITEM>\n          <ITEM>0.1</ITEM>").contains("<ITEM>[]</ITEM>")
                .contains("<ITEM><![CDATA[[]]]></ITEM>");
        KnowledgeBase context = KnowledgeBase.create();
        context.add(Frame.classFrame("SensorSignal").build());
        List<org.kicnp.core.xml.SourcedFrame> read = KnowledgeLoader.parseText(xml, "signal", context);

        assertThat(read).singleElement().satisfies(r -> {
            assertThat(r.frame().ownSlot("values").flatMap(Slot::value)).contains(nested);
            assertThat(r.frame().ownSlot("values").map(Slot::type)).contains(DataType.LIST);
        });
    }

    @Test
    void write_whenListsNestDeeperThanTheFormatAllows_refusesIt() {
        Value deep = Value.of("core");
        for (int i = 0; i < KnowledgeXmlWriter.MAX_NESTED_LISTS + 1; i++) {
            deep = new Value.Lst(List.of(deep));
        }
        Frame f = Frame.classFrame("B").slot(Slot.ofValue("s", DataType.LIST, deep)).build();

        assertThatThrownBy(() -> KnowledgeXmlWriter.toXml(f))
                .isInstanceOf(KnowledgeException.class)
                .hasMessage("The slot 's' of frame 'B' holds lists nested more than 16 deep, which the XML format "
                        + "cannot write.");
    }

    @Test
    void read_whenAListOfNumbersHoldsAList_refusesItAtItsSlot() {
        String xml = """
                <KNOWLEDGEBASE><FRAME><NAME>B</NAME><SLOTLIST><SLOT><NAME>s</NAME><TYPE>TYPE_LIST</TYPE>
                <ARGUMENT>TYPE_INT</ARGUMENT><VALUE><ITEM>1</ITEM><ITEM><ITEM>2</ITEM></ITEM></VALUE></SLOT></SLOTLIST>
                </FRAME></KNOWLEDGEBASE>""";

        assertThatThrownBy(() -> KnowledgeLoader.parseText(xml, "editor", KnowledgeBase.create()))
                .isInstanceOf(KnowledgeXmlException.class)
                .hasMessageContaining("an item holds ITEMs (a list inside a list), which only a list of TYPE_STR or "
                        + "TYPE_LIST items may hold, not one of TYPE_INT.");
    }

    @Test
    void write_whenTextHasALoneSurrogate_refusesIt() {
        Frame f = Frame.classFrame("B").slot(Slot.ofValue("s", DataType.STRING, Value.of("x\uD800y"))).build();

        assertThatThrownBy(() -> KnowledgeXmlWriter.toXml(f))
                .isInstanceOf(KnowledgeException.class)
                .hasMessage("The slot 's' of frame 'B' holds a lone surrogate U+D800, which is not a character and "
                        + "cannot be written.");
    }

    @Test
    void write_supplementaryCharacters_roundTrip() {
        Frame f = Frame.classFrame("B").slot(Slot.ofValue("s", DataType.STRING, Value.of("robot \uD83E\uDD16"))).build();

        Frame back = KnowledgeLoader.parseText(KnowledgeXmlWriter.toXml(f), "x", KnowledgeBase.create()).getFirst()
                .frame();

        assertThat(back).isEqualTo(f);
    }

    /**
     * Text the format reads as "absent" when plain (empty, white space, the word NULL in any case) is written in CDATA,
     * which the reader takes as written: a learned answer "" or "null" survives a save, and the journal, which holds
     * frames in this format, gives it back after a restart.
     */
    @ParameterizedTest
    @ValueSource(strings = {"", " ", "\t\n  ", "\r", " \r\n ", "NULL", "null", " Null\n"})
    void writeThenParse_stringThatPlainTextWouldReadAsAbsent_givesTheSameString(String text) {
        Frame f = Frame.classFrame("Answer")
                .slot(Slot.builder("said", DataType.STRING).value(Value.of(text)).build())
                .slot(Slot.builder("fallback", DataType.STRING).defaultValue(Value.of(text)).build())
                .slot(Slot.builder("heard", DataType.LIST).value(new Value.Lst(List.of(Value.of(text)))).build())
                .build();

        Frame back = KnowledgeLoader.parseText(KnowledgeXmlWriter.toXml(f), "x", KnowledgeBase.create())
                .getFirst().frame();

        assertThat(back.slots()).extracting(Slot::effectiveValue).containsExactly(Optional.of(Value.of(text)),
                Optional.of(Value.of(text)), Optional.of(new Value.Lst(List.of(Value.of(text)))));
        assertThat(back).isEqualTo(f);
    }

    /** Frame and slot names, references and relations may be NULL in any case; written in CDATA they read back. */
    @ParameterizedTest
    @ValueSource(strings = {"NULL", "null", "Null"})
    void writeThenParse_namesSpelledNull_giveTheSameFrames(String name) {
        Frame root = Frame.classFrame(name).build();
        Frame user = Frame.instance("user1", name)
                .part(name)
                .linkTo(new Relation.Named(name.toLowerCase(java.util.Locale.ROOT)), name)
                .slot(Slot.builder(name, DataType.INSTANCE).argument(name).value(Value.ref(name)).frameRelated(name)
                        .frameListRelated(List.of(name)).build())
                .build();

        List<Frame> back = KnowledgeLoader.parseText(save(List.of(root, user)), "x", KnowledgeBase.create()).stream()
                .map(SourcedFrame::frame).toList();

        assertThat(back).containsExactly(root, user);
    }

    @Test
    void parse_emptyOrNullTextOutsideCdata_isStillAbsentAsTable4PrintsIt() {
        String xml = """
                <FRAME><NAME>X</NAME><ISA>NULL</ISA><SLOTLIST>
                  <SLOT><NAME>a</NAME><TYPE>TYPE_STR</TYPE><VALUE></VALUE></SLOT>
                  <SLOT><NAME>b</NAME><TYPE>TYPE_STR</TYPE><VALUE> NULL </VALUE><ARGUMENT>null</ARGUMENT></SLOT>
                  <SLOT><NAME>c</NAME><TYPE>TYPE_STR</TYPE><VALUE><![CDATA[]]></VALUE></SLOT>
                </SLOTLIST></FRAME>
                """;

        Frame x = KnowledgeLoader.parseText(xml, "x", KnowledgeBase.create()).getFirst().frame();

        assertThat(x.parent()).isEmpty();
        assertThat(x.ownSlot("a").orElseThrow().value()).isEmpty();
        assertThat(x.ownSlot("b").orElseThrow().value()).isEmpty();
        assertThat(x.ownSlot("b").orElseThrow().argument()).isEmpty();
        assertThat(x.ownSlot("c").orElseThrow().value()).contains(Value.of(""));
    }
}
