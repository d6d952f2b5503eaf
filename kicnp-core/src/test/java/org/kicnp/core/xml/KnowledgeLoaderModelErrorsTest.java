package org.kicnp.core.xml;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.kicnp.core.xml.LoaderErrorFiles.classFrame;
import static org.kicnp.core.xml.LoaderErrorFiles.errors;
import static org.kicnp.core.xml.LoaderErrorFiles.kb;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;

/**
 * Loading well-formed files whose frames break the frame model together (a frame defined twice, IS-A cycles, missing
 * classes, descendants that disagree), and paths that name nothing: every problem reported, the knowledge base left
 * as it was.
 */
class KnowledgeLoaderModelErrorsTest {
    @TempDir Path dir;

    private Path file(String name, String xml) throws IOException {
        return LoaderErrorFiles.write(dir, name, xml);
    }

    @Test
    void load_whenFrameDefinedInTwoFiles_namesBothLocations() throws IOException {
        Path a = file("a.xml", kb(classFrame("Robot", null)));
        Path b = file("b.xml", kb(classFrame("Other", null), classFrame("Robot", null)));

        assertThat(errors(List.of(a, b))).containsExactly(
                b + ":6:3: Frame 'Robot' is defined twice: here and at " + a + ":2:3.");
    }

    @Test
    void load_whenIsACycle_reportsEachFrameOfTheCycle() throws IOException {
        Path a = file("a.xml", kb(classFrame("A", "B"), classFrame("B", "A")));

        assertThat(errors(List.of(a))).containsExactly(
                a + ":4:5: Frame 'A' is a kind of 'B', which makes an IS-A cycle: A -> B -> A.",
                a + ":9:5: Frame 'B' is a kind of 'A', which makes an IS-A cycle: B -> A -> B.");
    }

    /**
     * A long IS-A cycle (a file of 20,000 frames, each a kind of the next, about 1 MB) used to be walked again for
     * every frame and spelt out whole in every frame's error: a load ran for about a minute and ended in an
     * OutOfMemoryError. Each frame's error now names the start of the cycle only, and the load fails in moments.
     */
    @Test
    @org.junit.jupiter.api.Timeout(value = 20, threadMode = org.junit.jupiter.api.Timeout.ThreadMode.SEPARATE_THREAD)
    void load_whenIsACycleIsVeryLong_failsQuicklyWithShortErrors() throws IOException {
        int n = 20_000;
        StringBuilder xml = new StringBuilder("<KNOWLEDGEBASE>\n");
        for (int i = 0; i < n; i++) {
            xml.append("<FRAME><NAME>C").append(i).append("</NAME><ISA>C").append((i + 1) % n).append("</ISA></FRAME>\n");
        }
        Path a = file("a.xml", xml.append("</KNOWLEDGEBASE>\n").toString());

        List<String> errors = errors(List.of(a));

        assertThat(errors).hasSize(n);
        assertThat(errors.getFirst()).isEqualTo(a + ":2:23: Frame 'C0' is a kind of 'C1', which makes an IS-A cycle: "
                + "C0 -> C1 -> C2 -> C3 -> C4 -> C5 -> C6 -> C7 -> C8 -> C9 -> and further frames.");
        assertThat(errors).allSatisfy(err -> assertThat(err).hasSizeLessThan(a.toString().length() + 200));
    }

    @Test
    void load_whenSlotArgumentClassMissing_reportsTheSlot() throws IOException {
        Path a = file("a.xml", """
                <FRAME>
                  <NAME>X</NAME>
                  <SLOTLIST>
                    <SLOT>
                      <NAME>ok</NAME>
                      <TYPE>TYPE_STR</TYPE>
                    </SLOT>
                    <SLOT>
                      <NAME>who</NAME>
                      <TYPE>TYPE_INSTANCE</TYPE>
                      <ARGUMENT>Nobody</ARGUMENT>
                    </SLOT>
                  </SLOTLIST>
                </FRAME>
                """);

        assertThat(errors(List.of(a))).containsExactly(a + ":8:5: Slot 'who' of frame 'X' names class 'Nobody' as "
                + "its ARGUMENT, which is not defined.");
    }

    @Test
    void load_whenSlotNamedTwice_reportsTheSecond() throws IOException {
        Path a = file("a.xml", """
                <FRAME>
                  <NAME>X</NAME>
                  <SLOTLIST>
                    <SLOT><NAME>s</NAME><TYPE>TYPE_STR</TYPE></SLOT>
                    <SLOT><NAME>s</NAME><TYPE>TYPE_STR</TYPE></SLOT>
                  </SLOTLIST>
                </FRAME>
                """);

        assertThat(errors(List.of(a))).containsExactly(a + ":5:5: Frame 'X' has a second slot named 's'; slot names "
                + "must be unique within a frame.");
    }

    @Test
    void load_whenInstanceSlotHasNoTypeAnywhere_reportsTheSlot() throws IOException {
        Path a = file("a.xml", kb(classFrame("C", null), """
                  <FRAME>
                    <NAME>i</NAME>
                    <ISA>C</ISA>
                    <ISINSTANCE>TRUE</ISINSTANCE>
                    <SLOTLIST>
                      <SLOT><NAME>speed</NAME><VALUE>3</VALUE></SLOT>
                    </SLOTLIST>
                  </FRAME>
                """));

        assertThat(errors(List.of(a))).containsExactly(a + ":11:7: Slot 'speed' of frame 'i' has no TYPE, and no "
                + "frame above it declares a slot 'speed'.");
    }

    @Test
    void load_whenDescendantsDisagreeWithHierarchy_reportsThem() throws IOException {
        Path a = file("a.xml", kb("""
                  <FRAME>
                    <NAME>Robot</NAME>
                    <DESCENDANTS><FRAME>Humanoid</FRAME><FRAME>Wheeled</FRAME></DESCENDANTS>
                  </FRAME>
                """, classFrame("Humanoid", "Robot")));

        assertThat(errors(List.of(a))).containsExactly(a + ":4:5: Frame 'Robot' lists DESCENDANTS 'Humanoid', "
                + "'Wheeled', but the frames that are a kind of it are 'Humanoid'; descendants are derived from ISA, "
                + "so list them exactly or leave DESCENDANTS empty.");
    }

    @Test
    void load_whenAnyErrorOccurs_leavesTheKnowledgeBaseExactlyAsBefore() throws IOException {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("Existing").build());
        List<Frame> framesBefore = kb.frames();
        long versionBefore = kb.version();
        Path good = file("good.xml", kb(classFrame("Robot", "Existing"), classFrame("Humanoid", "Robot")));
        Path bad = file("bad.xml", kb(classFrame("Orphan", "Nowhere")));

        assertThatThrownBy(() -> KnowledgeLoader.load(kb, List.of(good, bad)))
                .isInstanceOf(KnowledgeXmlException.class)
                .hasMessage(bad + ":4:5: Frame 'Orphan' is a kind of 'Nowhere', which is not defined.");

        assertThat(kb.frames()).isEqualTo(framesBefore);
        assertThat(kb.version()).isEqualTo(versionBefore);
    }

    @Test
    void load_whenFrameAlreadyInTheKnowledgeBase_reportsTheFrame() throws IOException {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("Robot").build());
        Path a = file("a.xml", kb(classFrame("Robot", null)));

        assertThatThrownBy(() -> KnowledgeLoader.load(kb, List.of(a)))
                .isInstanceOf(KnowledgeXmlException.class)
                .hasMessage(a + ":2:3: A frame named 'Robot' already exists.");
    }

    @Test
    void load_whenSeveralFilesHaveErrors_reportsThemAll() throws IOException {
        Path a = file("a.xml", "<KNOWLEDGEBASE><FRAME><NAME>A</NAME><ISINSTANCE>perhaps</ISINSTANCE></FRAME>"
                + "</KNOWLEDGEBASE>");
        Path b = file("b.xml", "<KNOWLEDGEBASE><FRAM/></KNOWLEDGEBASE>");

        assertThat(errors(List.of(a, b))).containsExactly(
                a + ":1:37: Frame 'A' has ISINSTANCE 'perhaps', which is not a boolean; write TRUE or FALSE.",
                b + ":1:16: Unknown element 'FRAM' in KNOWLEDGEBASE; expected FRAME.");
    }

    @Test
    void expand_whenAPathIsEmpty_refusesItRatherThanListingTheWorkingDirectory() throws IOException {
        Path a = file("a.xml", kb(classFrame("A", null)));

        assertThatThrownBy(() -> KnowledgeLoader.expand(List.of(a, Path.of(""))))
                .isInstanceOf(KnowledgeXmlException.class)
                .hasMessage("'':1:1: An empty path names no file or directory; write '.' for the current directory.");
    }

    @Test
    void expand_whenPathMissing_namesIt() {
        Path missing = dir.resolve("nope.xml");

        assertThatThrownBy(() -> KnowledgeLoader.expand(List.of(missing)))
                .isInstanceOf(KnowledgeXmlException.class)
                .hasMessage(missing + ":1:1: No such file or directory: '" + missing + "'.");
    }

    @Test
    void load_whenRootIsUnknown_saysWhatARootMustBe() throws IOException {
        Path a = file("a.xml", "<FRAMES/>");

        assertThat(errors(List.of(a))).containsExactly(a + ":1:1: The root element is 'FRAMES'; a knowledge file "
                + "holds KNOWLEDGEBASE or a single FRAME.");
    }
}
