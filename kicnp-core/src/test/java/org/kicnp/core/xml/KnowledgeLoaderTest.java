package org.kicnp.core.xml;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

class KnowledgeLoaderTest {
    @TempDir Path dir;

    private Path file(String name, String xml) throws IOException {
        Path p = dir.resolve(name);
        Files.createDirectories(p.getParent());
        Files.writeString(p, xml);
        return p;
    }

    @Test
    void load_singleFrameFile_isAKnowledgeFile() throws IOException {
        Path p = file("one.xml", "<FRAME><NAME>Robot</NAME><ISA>NULL</ISA><ISINSTANCE>false</ISINSTANCE></FRAME>");
        KnowledgeBase kb = KnowledgeBase.create();

        List<SourcedFrame> loaded = KnowledgeLoader.load(kb, List.of(p));

        assertThat(loaded).singleElement().isEqualTo(
                new SourcedFrame(Frame.classFrame("Robot").build(), new SourceLocation(p.toString(), 1, 1)));
        assertThat(kb.roots()).extracting(Frame::name).containsExactly("Robot");
    }

    @Test
    void load_directory_readsXmlFilesBelowInPathOrderAndSkipsHiddenOnes() throws IOException {
        file("b/robots.xml", "<KNOWLEDGEBASE><FRAME><NAME>Robot</NAME><ISA>System</ISA></FRAME></KNOWLEDGEBASE>");
        file("a.xml", "<FRAME><NAME>System</NAME></FRAME>");
        file(".kicnp/journal.xml", "<FRAME><NAME>Hidden</NAME></FRAME>");
        file("b/.draft.xml", "<FRAME><NAME>Draft</NAME></FRAME>");
        file("notes.txt", "not a knowledge file");

        assertThat(KnowledgeLoader.expand(List.of(dir)))
                .containsExactly(dir.resolve("a.xml"), dir.resolve("b/robots.xml"));
        KnowledgeBase kb = KnowledgeBase.create();
        KnowledgeLoader.load(kb, List.of(dir));
        assertThat(kb.frames()).extracting(Frame::name).containsExactly("System", "Robot");
    }

    @Test
    void load_whenParentIsInALaterFile_resolvesItInOneBatch() throws IOException {
        Path a = file("a.xml", "<FRAME><NAME>Robot</NAME><ISA>System</ISA></FRAME>");
        Path b = file("b.xml", "<FRAME><NAME>System</NAME></FRAME>");
        KnowledgeBase kb = KnowledgeBase.create();

        KnowledgeLoader.load(kb, List.of(a, b));

        assertThat(kb.isA("Robot", "System")).isTrue();
        assertThat(kb.version()).isEqualTo(1);
    }

    @Test
    void load_whenInstanceSlotHasNoType_takesItFromTheNearestDeclarationInAnyFileOrTheKnowledgeBase()
            throws IOException {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("Robot").slot(Slot.builder("speed", DataType.FLOAT).build()).build());
        Path a = file("a.xml", """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>r1</NAME><ISA>Humanoid</ISA><ISINSTANCE>TRUE</ISINSTANCE>
                    <SLOTLIST>
                      <SLOT><NAME>speed</NAME><VALUE>2</VALUE></SLOT>
                      <SLOT><NAME>legs</NAME><VALUE>2</VALUE></SLOT>
                    </SLOTLIST>
                  </FRAME>
                </KNOWLEDGEBASE>
                """);
        Path b = file("b.xml", """
                <FRAME><NAME>Humanoid</NAME><ISA>Robot</ISA>
                  <SLOTLIST><SLOT><NAME>legs</NAME><TYPE>TYPE_INT</TYPE></SLOT></SLOTLIST>
                </FRAME>
                """);

        KnowledgeLoader.load(kb, List.of(a, b));

        Frame r1 = kb.require("r1");
        assertThat(r1.ownSlot("speed").orElseThrow().value()).contains(Value.of(2.0));
        assertThat(r1.ownSlot("legs").orElseThrow().value()).contains(Value.of(2L));
        assertThat(kb.frames()).extracting(Frame::name).containsExactly("Robot", "r1", "Humanoid");
    }

    @Test
    void load_whenAListSlotGivesNoArgument_readsItsItemsAsTheInheritedArgumentSays() throws IOException {
        // the instance comes first: the class it inherits the item types from is read after it
        Path users = file("users.xml", """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>userA</NAME><ISA>KnownUser</ISA><ISINSTANCE>TRUE</ISINSTANCE>
                    <SLOTLIST>
                      <SLOT><NAME>face</NAME><TYPE>TYPE_LIST</TYPE><VALUE><ITEM>0.5</ITEM><ITEM>-1</ITEM></VALUE></SLOT>
                      <SLOT><NAME>friends</NAME><VALUE><ITEM>userB</ITEM></VALUE></SLOT>
                    </SLOTLIST>
                  </FRAME>
                  <FRAME><NAME>userB</NAME><ISA>KnownUser</ISA><ISINSTANCE>TRUE</ISINSTANCE></FRAME>
                </KNOWLEDGEBASE>
                """);
        Path classes = file("z-classes.xml", """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>User</NAME>
                    <SLOTLIST>
                      <SLOT><NAME>face</NAME><TYPE>TYPE_LIST</TYPE><ARGUMENT>TYPE_FLOAT</ARGUMENT></SLOT>
                      <SLOT><NAME>friends</NAME><TYPE>TYPE_LIST</TYPE><ARGUMENT>User</ARGUMENT></SLOT>
                    </SLOTLIST>
                  </FRAME>
                  <FRAME><NAME>KnownUser</NAME><ISA>User</ISA></FRAME>
                </KNOWLEDGEBASE>
                """);
        KnowledgeBase kb = KnowledgeBase.create();

        KnowledgeLoader.load(kb, List.of(users, classes));

        assertThat(kb.value("userA", "face")).contains(new Value.Lst(List.of(Value.of(0.5), Value.of(-1.0))));
        assertThat(kb.value("userA", "friends")).contains(new Value.Lst(List.of(Value.ref("userB"))));
        assertThat(kb.require("userA").ownSlot("face").orElseThrow().argument()).isEmpty();
    }

    @Test
    void load_whenAListItemDoesNotFitTheInheritedArgument_saysSo() throws IOException {
        Path p = file("kb.xml", """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>User</NAME>
                    <SLOTLIST><SLOT><NAME>face</NAME><TYPE>TYPE_LIST</TYPE><ARGUMENT>TYPE_FLOAT</ARGUMENT></SLOT></SLOTLIST>
                  </FRAME>
                  <FRAME><NAME>userA</NAME><ISA>User</ISA><ISINSTANCE>TRUE</ISINSTANCE>
                    <SLOTLIST><SLOT><NAME>face</NAME><VALUE><ITEM>wide</ITEM></VALUE></SLOT></SLOTLIST>
                  </FRAME>
                </KNOWLEDGEBASE>
                """);

        KnowledgeXmlException e = org.assertj.core.api.Assertions.catchThrowableOfType(KnowledgeXmlException.class,
                () -> KnowledgeLoader.load(KnowledgeBase.create(), List.of(p)));

        assertThat(e).isNotNull();
        assertThat(e.errors()).extracting(LoadError::format).containsExactly(p + ":6:38: Slot 'face' of frame 'userA' "
                + "has a VALUE that does not fit its type TYPE_LIST: 'wide' is not a number.");
    }

    @Test
    void writeThenLoad_ofAnInstanceListOfTheClassesItemType_givesTheSameFrame() throws IOException {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("User").slot(Slot.builder("face", DataType.LIST).argument("TYPE_FLOAT").build()).build());
        Frame userA = Frame.instance("userA", "User").provenance(org.kicnp.core.Provenance.LEARNED)
                .slot(Slot.ofValue("face", DataType.LIST, new Value.Lst(List.of(Value.of(0.25), Value.of(2.0)))))
                .build();
        kb.add(userA);
        Path p = dir.resolve("saved.xml");
        KnowledgeXmlWriter.write(kb.frames(), p);

        KnowledgeBase again = KnowledgeBase.create();
        KnowledgeLoader.load(again, List.of(p));

        assertThat(again.require("userA")).isEqualTo(userA);
    }

    /**
     * The reader reads a list's items as its ARGUMENT (or the inherited one) says, so a list holding items of another
     * type, such as a script's ["abc"] for a TYPE_INT list, was saved (and journalled) into XML that the loader then
     * refused. The knowledge base now refuses such a list when it is given; an integer in a TYPE_FLOAT list is
     * allowed, as in a TYPE_FLOAT slot, and reads back as a float. Lists of TYPE_STR or with no ARGUMENT take any
     * items, which read back as strings (see docs/xml-format.md).
     */
    @Test
    void add_whenAListItemCannotBeReadBackAsTheArgumentSays_isRefusedSoThatWhatIsKeptCanBeSavedAndLoaded()
            throws IOException {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("User").slot(Slot.builder("visits", DataType.LIST).argument("TYPE_INT").build())
                .slot(Slot.builder("face", DataType.LIST).argument("TYPE_FLOAT").build())
                .slot(Slot.builder("friends", DataType.LIST).argument("User").build()).build());
        Frame wrong = Frame.instance("userA", "User")
                .slot(Slot.ofValue("visits", DataType.LIST, new Value.Lst(List.of(Value.of(3L), Value.of("abc")))))
                .slot(Slot.ofValue("friends", DataType.LIST, new Value.Lst(List.of(Value.of("userB"))))).build();

        org.assertj.core.api.Assertions.assertThatThrownBy(() -> kb.add(wrong))
                .isInstanceOf(org.kicnp.core.BatchRejectedException.class)
                .hasMessageContaining("Slot 'visits' of frame 'userA' holds the list item 'abc', a TYPE_STR, but its "
                        + "ARGUMENT makes it a list of TYPE_INT.")
                .hasMessageContaining("Slot 'friends' of frame 'userA' holds the list item 'userB', a TYPE_STR, but its "
                        + "ARGUMENT makes it a list of instances of 'User'.");
        Frame right = Frame.instance("userA", "User")
                .slot(Slot.ofValue("face", DataType.LIST, new Value.Lst(List.of(Value.of(0.5), Value.of(2L))))).build();
        kb.add(right);
        Path p = dir.resolve("saved.xml");
        KnowledgeXmlWriter.write(kb.frames(), p);

        KnowledgeBase again = KnowledgeBase.create();
        KnowledgeLoader.load(again, List.of(p));

        assertThat(again.require("userA").ownSlot("face").orElseThrow().value())
                .contains(new Value.Lst(List.of(Value.of(0.5), Value.of(2.0))));
    }

    @Test
    void parse_changesNothing() throws IOException {
        Path a = file("a.xml", "<FRAME><NAME>System</NAME></FRAME>");
        KnowledgeBase kb = KnowledgeBase.create();

        List<SourcedFrame> parsed = KnowledgeLoader.parse(List.of(a), kb);

        assertThat(parsed).extracting(s -> s.frame().name()).containsExactly("System");
        assertThat(kb.size()).isZero();
        assertThat(kb.version()).isZero();
    }

    @Test
    void load_linksPartsAndDescendants_areReadAsTable1Items() throws IOException {
        Path a = file("a.xml", """
                <KNOWLEDGEBASE>
                  <FRAME>
                    <NAME>Robot</NAME>
                    <DESCENDANTS><FRAME>Arm</FRAME><ITEM>Move</ITEM></DESCENDANTS>
                  </FRAME>
                  <FRAME><NAME>Arm</NAME><ISA>Robot</ISA></FRAME>
                  <FRAME>
                    <NAME>Move</NAME>
                    <ISA>Robot</ISA>
                    <HASPART><PART>Arm</PART></HASPART>
                    <SEMANTICLINKTO>
                      <LINK><RELATION>synchronization</RELATION><TARGET>Arm</TARGET></LINK>
                      <LINK><RELATION>follows</RELATION><TARGET>Robot</TARGET></LINK>
                    </SEMANTICLINKTO>
                    <LEARNED>TRUE</LEARNED>
                    <PRIORITY>3</PRIORITY>
                  </FRAME>
                </KNOWLEDGEBASE>
                """);
        KnowledgeBase kb = KnowledgeBase.create();

        KnowledgeLoader.load(kb, List.of(a));

        Frame move = kb.require("Move");
        assertThat(move.parts()).containsExactly("Arm");
        assertThat(move.linksTo()).extracting(l -> l.relation().name() + "->" + l.frame())
                .containsExactly("SYNCHRONIZATION->Arm", "follows->Robot");
        assertThat(move.learned()).isTrue();
        assertThat(move.priority()).isEqualTo(3);
        assertThat(kb.linksInto("Arm")).hasSize(1);
    }

    @Test
    void parseText_largeInput_isMappedWhileReadingWithTheSameResultAndErrorOrder() {
        List<Frame> frames = XmlBenchMain.generate(3600);
        java.io.StringWriter out = new java.io.StringWriter();
        KnowledgeXmlWriter.write(frames, out);
        String xml = out.toString();
        assertThat((long) xml.length()).isGreaterThan(KnowledgeLoader.PIPELINE_CHARS);

        List<SourcedFrame> back = KnowledgeLoader.parseText(xml, "big", KnowledgeBase.create());
        assertThat(back).extracting(SourcedFrame::frame).isEqualTo(frames);

        String broken = xml.replace("<NAME>C10</NAME>", "<NAME>C10</NAME><COLOUR>red</COLOUR>")
                .replaceFirst("<VALUE>10</VALUE>", "<VALUE>ten</VALUE>");
        KnowledgeXmlException e = org.assertj.core.api.Assertions.catchThrowableOfType(KnowledgeXmlException.class,
                () -> KnowledgeLoader.parseText(broken, "big", KnowledgeBase.create()));
        assertThat(e.errors()).extracting(LoadError::message).satisfiesExactly(
                m -> assertThat(m).startsWith("Unknown element 'COLOUR' in FRAME"),
                m -> assertThat(m).isEqualTo("Slot 'count' of frame 'C10' has a VALUE that does not fit its type "
                        + "TYPE_INT: 'ten' is not an integer."));
    }

    @Test
    void load_schemaAttributesOnTheRoot_areAllowedButOtherAttributesAreErrors() throws IOException {
        Path ok = file("ok.xml", "<KNOWLEDGEBASE xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
                + "xsi:noNamespaceSchemaLocation=\"kicnp-kb.xsd\"><FRAME><NAME>A</NAME></FRAME></KNOWLEDGEBASE>");
        Path bad = file("bad.xml", "<KNOWLEDGEBASE>\n  <FRAME id=\"1\"><NAME>B</NAME></FRAME>\n</KNOWLEDGEBASE>");

        assertThat(KnowledgeLoader.parse(List.of(ok), KnowledgeBase.create())).hasSize(1);
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> KnowledgeLoader.parse(List.of(bad),
                        KnowledgeBase.create()))
                .isInstanceOf(KnowledgeXmlException.class)
                .hasMessage(bad + ":2:3: Element FRAME has attribute 'id'; the format uses elements only.");
    }

    @Test
    void load_conditionsInCdataOrEscaped_areParsed() throws IOException {
        Path a = file("a.xml", """
                <FRAME>
                  <NAME>X</NAME>
                  <SLOTLIST>
                    <SLOT><NAME>a</NAME><TYPE>TYPE_INT</TYPE><CONDITION>&lt;= 5</CONDITION></SLOT>
                    <SLOT><NAME>b</NAME><TYPE>TYPE_INT</TYPE><CONDITION><![CDATA[js: s.a < 3 && s.b]]></CONDITION></SLOT>
                  </SLOTLIST>
                </FRAME>
                """);

        Frame x = KnowledgeLoader.parse(List.of(a), KnowledgeBase.create()).getFirst().frame();

        assertThat(x.ownSlot("a").orElseThrow().condition().text()).isEqualTo("<= 5");
        assertThat(x.ownSlot("b").orElseThrow().condition().text()).isEqualTo("js: s.a < 3 && s.b");
    }

    /** Frame names may hold '-' (AIBO-1), so a condition's constant reference {@code @AIBO-1} must name that frame. */
    @Test
    void loadSaveLoad_conditionReferringToAFrameWithAHyphenInItsName_keepsTheWholeName() throws IOException {
        Path a = file("a.xml", """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Robot</NAME></FRAME>
                  <FRAME><NAME>AIBO-1</NAME><ISA>Robot</ISA><ISINSTANCE>TRUE</ISINSTANCE></FRAME>
                  <FRAME>
                    <NAME>Follow</NAME>
                    <SLOTLIST>
                      <SLOT><NAME>leader</NAME><TYPE>TYPE_INSTANCE</TYPE><ARGUMENT>Robot</ARGUMENT>
                        <CONDITION>== @AIBO-1</CONDITION></SLOT>
                      <SLOT><NAME>team</NAME><TYPE>TYPE_INSTANCE</TYPE><ARGUMENT>Robot</ARGUMENT>
                        <CONDITION>in (@AIBO-1, @Robot)</CONDITION></SLOT>
                    </SLOTLIST>
                  </FRAME>
                </KNOWLEDGEBASE>
                """);
        KnowledgeBase kb = KnowledgeBase.create();
        KnowledgeLoader.load(kb, List.of(a));
        Path saved = dir.resolve("saved.xml");
        KnowledgeXmlWriter.write(kb.frames(), saved);

        KnowledgeBase again = KnowledgeBase.create();
        KnowledgeLoader.load(again, List.of(saved));

        Frame follow = again.require("Follow");
        assertThat(follow.ownSlot("leader").orElseThrow().condition().operands())
                .containsExactly(new org.kicnp.core.Operand.Constant(Value.ref("AIBO-1")));
        assertThat(follow.ownSlot("team").orElseThrow().condition().text()).isEqualTo("in (@AIBO-1, @Robot)");
        assertThat(again.frames()).isEqualTo(kb.frames());
    }

    /** Comments are not kept, but the text around them is, white space included. */
    @Test
    void parse_textBrokenByComments_keepsAllTheTextAroundThem() {
        String xml = "<FRAME><NAME>X</NAME><SLOTLIST><SLOT><NAME>s</NAME><TYPE>TYPE_STR</TYPE>"
                + "<VALUE>  <!-- a -->  <!-- b -->x</VALUE></SLOT></SLOTLIST></FRAME>";

        Frame x = KnowledgeLoader.parseText(xml, "x", KnowledgeBase.create()).getFirst().frame();

        assertThat(x.ownSlot("s").orElseThrow().value()).contains(Value.of("    x"));
    }
}
