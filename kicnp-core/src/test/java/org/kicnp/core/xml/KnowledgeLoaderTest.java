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
}
