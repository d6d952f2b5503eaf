package org.kicnp.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.store.KnowledgeStore;
import org.kicnp.core.store.StoreOptions;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.core.xml.SourcedFrame;

class ValidateCommandTest {
    private static final String BASE = """
            <KNOWLEDGEBASE>
              <FRAME><NAME>System</NAME><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
              <FRAME><NAME>Speech</NAME><ISA>System</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
              <FRAME><NAME>Mouth</NAME><ISA>System</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
              <FRAME><NAME>KnownUser</NAME><ISA>System</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
              <FRAME><NAME>RobovieMouth</NAME><ISA>Mouth</ISA><ISINSTANCE>TRUE</ISINSTANCE></FRAME>
            </KNOWLEDGEBASE>
            """;

    /** The frame of the paper's Table 4, whose parent Speech is declared in another file. */
    private static final String GREETING = """
            <FRAME>
              <NAME>Greeting</NAME>
              <ISA>%s</ISA>
              <ISINSTANCE>FALSE</ISINSTANCE>
              <SLOTLIST>
                <SLOT>
                  <NAME>mUser</NAME>
                  <TYPE>TYPE_INSTANCE</TYPE>
                  <CONDITION>COND_ANY</CONDITION>
                  <ARGUMENT>KnownUser</ARGUMENT>
                  <VALUE></VALUE>
                  <REQUIRED>TRUE</REQUIRED>
                  <SHARED>TRUE</SHARED>
                  <UNIQUE>TRUE</UNIQUE>
                </SLOT>
                <SLOT>
                  <NAME>mMouth</NAME>
                  <TYPE>TYPE_INSTANCE</TYPE>
                  <CONDITION>COND_ANY</CONDITION>
                  <ARGUMENT>Mouth</ARGUMENT>
                  <VALUE></VALUE>
                  <REQUIRED>TRUE</REQUIRED>
                  <SHARED>TRUE</SHARED>
                  <UNIQUE>TRUE</UNIQUE>
                </SLOT>
                <SLOT>
                  <NAME>onInstantiate</NAME>
                  <TYPE>TYPE_STR</TYPE>
                  <CONDITION>COND_ANY</CONDITION>
                  <ARGUMENT></ARGUMENT>
                  <VALUE>Sendmsg(s.mMouth, “Hi! Nice to meet you. Welcome to visit my room!”);</VALUE>
                  <REQUIRED>FALSE</REQUIRED>
                  <SHARED>TRUE</SHARED>
                  <UNIQUE>TRUE</UNIQUE>
                </SLOT>
              </SLOTLIST>
            </FRAME>
            """;

    @TempDir
    Path dir;

    @Test
    void validate_whenDirectoryLoadsAcrossFiles_exitsZeroAndCountsFrames() throws IOException {
        Files.writeString(dir.resolve("base.xml"), BASE);
        Files.writeString(dir.resolve("greeting.xml"), GREETING.formatted("Speech"));

        CliRun run = CliRun.of("validate", dir.toString());

        assertThat(run.exitCode()).as(run.out() + run.err()).isZero();
        assertThat(run.outLines()).containsExactly("OK: 6 frames (5 classes, 1 instance) from 2 files");
    }

    @Test
    void validate_whenParentMissing_reportsFileLineAndColumn() throws IOException {
        Files.writeString(dir.resolve("base.xml"), BASE);
        Path greeting = dir.resolve("greeting.xml");
        Files.writeString(greeting, GREETING.formatted("Conversation"));

        CliRun run = CliRun.of("validate", dir.toString());

        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.outLines()).hasSize(2);
        assertThat(run.outLines().get(0)).startsWith(greeting + ":" + MISSING_PARENT_AT + ": ").contains("'Conversation'");
        assertThat(run.outLines().get(1)).startsWith("FAILED: 1 error in 1 file");
    }

    @Test
    void validate_whenSeveralFilesHaveErrors_printsOneLinePerErrorThenASummary() throws IOException {
        Path base = dir.resolve("base.xml");
        Files.writeString(base, BASE.replace("<ISA>System</ISA>", "<ISA>Sistem</ISA>"));
        Path greeting = dir.resolve("greeting.xml");
        Files.writeString(greeting, GREETING.formatted("Conversation"));

        CliRun run = CliRun.of("validate", base.toString(), greeting.toString());

        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.outLines()).filteredOn(l -> l.startsWith(base + ":")).hasSize(3)
                .allSatisfy(l -> assertThat(l).matches(".*:\\d+:\\d+: .*'Sistem'.*"));
        assertThat(run.outLines()).filteredOn(l -> l.startsWith(greeting + ":")).hasSize(1);
        assertThat(run.outLines().get(run.outLines().size() - 1)).isEqualTo("FAILED: 4 errors in 2 files (of 2 files checked)");
    }

    @Test
    void validate_whenAScriptOrScriptConditionDoesNotParse_reportsItsFrameSlotLineAndColumn() throws IOException {
        Files.writeString(dir.resolve("base.xml"), BASE);
        Path greeting = dir.resolve("greeting.xml");
        Files.writeString(greeting, GREETING.formatted("Speech")
                .replace("Sendmsg(s.mMouth, “Hi!", "Sendmsg(s.mMouth, (“Hi!")
                .replace("<CONDITION>COND_ANY</CONDITION>\n      <ARGUMENT>Mouth</ARGUMENT>",
                        "<CONDITION>js: s.mMouth.on &amp;&amp;</CONDITION>\n      <ARGUMENT>Mouth</ARGUMENT>"));

        CliRun run = CliRun.of("validate", dir.toString());

        assertThat(run.exitCode()).as(run.out()).isEqualTo(1);
        assertThat(run.outLines()).hasSize(3);
        assertThat(run.outLines().get(0)).startsWith(greeting + ":1:1: The js: condition of slot 'mMouth' of frame "
                + "'Greeting' has a syntax error at line 1, column ");
        assertThat(run.outLines().get(1)).startsWith(greeting + ":1:1: The script in slot 'onInstantiate' of frame "
                + "'Greeting' has a syntax error at line 1, column ");
        assertThat(run.outLines().get(2)).isEqualTo("FAILED: 2 errors in 1 file (of 2 files checked)");
    }

    @Test
    void validate_whenXmlErrorsFrameProblemsAndScriptErrorsMix_reportsThemAllInOneRun() throws IOException {
        Files.writeString(dir.resolve("base.xml"), BASE);
        Path greeting = dir.resolve("greeting.xml");
        Files.writeString(greeting, GREETING.formatted("Speech").replace("Sendmsg(s.mMouth, “Hi!", "Sendmsg(s.mMouth, (“Hi!"));
        Path more = dir.resolve("more.xml");
        Files.writeString(more, """
                <KNOWLEDGEBASE>
                  <FRAME><NAME>Farewell</NAME><ISA>Speach</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>
                  <FRAME><NAME>Cup</NAME><ISINSTANCE>perhaps</ISINSTANCE></FRAME>
                </KNOWLEDGEBASE>
                """);

        CliRun run = CliRun.of("validate", dir.toString());

        assertThat(run.exitCode()).as(run.out()).isEqualTo(1);
        assertThat(run.outLines()).hasSize(4);
        assertThat(run.outLines().get(0)).startsWith(greeting + ":1:1: The script in slot 'onInstantiate' of frame "
                + "'Greeting' has a syntax error at line 1, column ");
        assertThat(run.outLines().get(1)).isEqualTo(more + ":2:31: Frame 'Farewell' is a kind of 'Speach', which is "
                + "not defined.");
        assertThat(run.outLines().get(2)).isEqualTo(more + ":3:26: Frame 'Cup' has ISINSTANCE 'perhaps', which is not "
                + "a boolean; write TRUE or FALSE.");
        assertThat(run.outLines().get(3)).isEqualTo("FAILED: 3 errors in 2 files (of 3 files checked)");
    }

    /** The directory as {@code serve} would open it: its XML files with the journal's changes replayed on top. */
    @Test
    void validate_whenTheStoreHasAJournal_validatesTheFilesWithTheJournalReplayedAndSaysWhatItHeld() throws IOException {
        Files.writeString(dir.resolve("base.xml"), BASE);
        journal(GREETING.formatted("Speech"));

        CliRun run = CliRun.of("validate", dir.toString());

        assertThat(run.exitCode()).as(run.out() + run.err()).isZero();
        assertThat(run.outLines()).containsExactly(
                "Journal: " + dir.resolve(".kicnp") + " holds 1 record not yet folded into the files; replayed on top "
                        + "of them, as serve would open the directory (1 frame added, 0 changed, 0 removed).",
                "OK: 6 frames (5 classes, 1 instance) from 1 file and the journal");
    }

    @Test
    void validate_whenAFrameOfTheJournalHasAScriptThatDoesNotParse_namesTheFrameSlotAndJournal() throws IOException {
        Files.writeString(dir.resolve("base.xml"), BASE);
        journal(GREETING.formatted("Speech").replace("Sendmsg(s.mMouth, “Hi!", "Sendmsg(s.mMouth, (“Hi!"));

        CliRun run = CliRun.of("validate", dir.toString());

        assertThat(run.exitCode()).as(run.out() + run.err()).isEqualTo(1);
        assertThat(run.outLines()).hasSize(3);
        assertThat(run.outLines().get(1)).startsWith(dir.resolve(".kicnp") + ":0:0: The script in slot 'onInstantiate' "
                + "of frame 'Greeting' has a syntax error at line 1, column ");
        assertThat(run.outLines().get(2)).isEqualTo("FAILED: 1 error in 1 file (of 1 file checked and the journal)");
    }

    @Test
    void validate_whenTheJournalNoLongerReplaysOntoEditedFiles_failsNamingTheFramesAndTheRecord() throws IOException {
        Files.writeString(dir.resolve("base.xml"), BASE);
        journal(GREETING.formatted("Speech"));
        Files.writeString(dir.resolve("base.xml"), BASE.replace(
                "<FRAME><NAME>Speech</NAME><ISA>System</ISA><ISINSTANCE>FALSE</ISINSTANCE></FRAME>", ""));

        CliRun run = CliRun.of("validate", dir.toString());

        assertThat(run.exitCode()).as(run.out() + run.err()).isEqualTo(1);
        assertThat(run.out()).contains(dir.resolve(".kicnp") + ":0:0: ").contains("'Greeting' changed by the journal "
                + "record journal-").contains("'Speech'");
        assertThat(run.outLines().get(run.outLines().size() - 1)).isEqualTo("FAILED: the journal does not replay onto "
                + "the knowledge files.");
        assertThat(Files.readString(dir.resolve("base.xml"))).doesNotContain("Greeting");
    }

    /** Adds the frames of {@code xml} to the store in {@link #dir} and closes it without folding the journal. */
    private void journal(String xml) throws IOException {
        Path source = Files.createTempDirectory(dir.getParent(), "src").resolve("frames.xml");
        Files.writeString(source, xml);
        StoreOptions keepJournal = StoreOptions.defaults().withFsync(false).withCompactOnClose(false)
                .withCompactInBackground(false);
        try (KnowledgeStore store = KnowledgeStore.open(dir, keepJournal)) {
            List<Frame> frames = KnowledgeLoader.parse(List.of(source), store.kb()).stream().map(SourcedFrame::frame)
                    .toList();
            store.kb().apply(frames.stream().<Change>map(Change.Add::new).toList());
        }
    }

    @Test
    void validate_whenXmlMalformed_reportsTheLineAndFails() throws IOException {
        Path broken = dir.resolve("broken.xml");
        Files.writeString(broken, "<FRAME>\n  <NAME>Oops</NAME>\n  <ISINSTANCE>FALSE</ISINST>\n</FRAME>\n");

        CliRun run = CliRun.of("validate", broken.toString());

        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.outLines().get(0)).startsWith(broken + ":3:");
    }

    @Test
    void validate_whenPathDoesNotExist_saysSoAndFails() {
        Path missing = dir.resolve("nowhere.xml");

        CliRun run = CliRun.of("validate", missing.toString());

        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.out()).contains(missing + ": no such file or directory.");
    }

    @Test
    void validate_whenAPathIsEmpty_saysSoInsteadOfCheckingTheWorkingDirectory() throws IOException {
        Files.writeString(dir.resolve("base.xml"), BASE);

        CliRun run = CliRun.of("validate", dir.toString(), "");

        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.out()).contains("'': An empty path names no file or directory; write '.' for the current "
                + "directory.").contains("FAILED: 1 path not found; nothing was loaded.").doesNotContain("OK");
    }

    @Test
    void validate_whenDirectoryHasNoKnowledgeFiles_fails() {
        CliRun run = CliRun.of("validate", dir.toString());

        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.out()).contains("no knowledge files");
    }

    @Test
    void validate_withoutArguments_isAUsageError() {
        CliRun run = CliRun.of("validate");

        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("FILE_OR_DIR");
    }

    @Test
    void validate_help_explainsAndSucceeds() {
        CliRun run = CliRun.of("validate", "--help");

        assertThat(run.exitCode()).isZero();
        assertThat(run.out()).contains("Usage: kicnp validate").contains("FILE:LINE:COLUMN");
    }

    /** Where the loader reports an unknown parent in GREETING: the ISA element, line 3. */
    private static final String MISSING_PARENT_AT = "3:3";
}
