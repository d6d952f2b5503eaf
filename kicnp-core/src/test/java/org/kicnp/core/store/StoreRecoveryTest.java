package org.kicnp.core.store;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.kicnp.core.store.StoreFixtures.QUIET;
import static org.kicnp.core.store.StoreFixtures.baseDir;
import static org.kicnp.core.store.StoreFixtures.journalSegments;
import static org.kicnp.core.store.StoreFixtures.learnedUser;
import static org.kicnp.core.store.StoreFixtures.robot;
import static org.kicnp.core.store.StoreFixtures.robotClass;
import static org.kicnp.core.store.StoreFixtures.userClass;

import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.kicnp.core.xml.KnowledgeXmlWriter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Opening a directory that a crash (or worse) left behind. */
class StoreRecoveryTest {
    @TempDir
    Path tmp;

    @Test
    void open_whenManifestSurvivedButNoRenameHappened_finishesTheRenames() throws Exception {
        Path dir = baseDir(tmp);
        Files.createDirectories(dir.resolve(".kicnp"));
        // A compaction wrote its new files and its manifest, then the process died before renaming anything.
        KnowledgeXmlWriter.write(List.of(userClass(), robotClass(), robot("robot1", 42)),
                dir.resolve("base.xml" + Compaction.TEMP_SUFFIX));
        KnowledgeXmlWriter.write(List.of(learnedUser("ann", 1)), dir.resolve("learned.xml" + Compaction.TEMP_SUFFIX));
        new Manifest(List.of(
                new Manifest.Rename(Path.of("base.xml" + Compaction.TEMP_SUFFIX), Path.of("base.xml")),
                new Manifest.Rename(Path.of("learned.xml" + Compaction.TEMP_SUFFIX), Path.of("learned.xml"))))
                .write(dir.resolve(".kicnp"), new Disk(false));

        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().require("robot1")).isEqualTo(robot("robot1", 42));
            assertThat(store.kb().require("ann")).isEqualTo(learnedUser("ann", 1));
            assertThat(store.homeOf("ann")).contains(dir.resolve("learned.xml"));
        }
        assertThat(StoreFixtures.files(dir).keySet()).containsExactlyInAnyOrder("base.xml", "learned.xml",
                ".kicnp/lock", ".kicnp/journal-00000000000000000001");
    }

    @Test
    void open_whenManifestSurvivedAfterSomeRenames_finishesTheRest() throws Exception {
        Path dir = baseDir(tmp);
        Files.createDirectories(dir.resolve(".kicnp"));
        Files.delete(dir.resolve("base.xml"));
        KnowledgeXmlWriter.write(List.of(userClass(), robotClass()), dir.resolve("base.xml")); // already renamed
        KnowledgeXmlWriter.write(List.of(robot("robot1", 5)), dir.resolve("robots.xml" + Compaction.TEMP_SUFFIX));
        new Manifest(List.of(
                new Manifest.Rename(Path.of("base.xml" + Compaction.TEMP_SUFFIX), Path.of("base.xml")),
                new Manifest.Rename(Path.of("robots.xml" + Compaction.TEMP_SUFFIX), Path.of("robots.xml")),
                new Manifest.Delete(Path.of("gone.xml"))))
                .write(dir.resolve(".kicnp"), new Disk(false));

        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().require("robot1")).isEqualTo(robot("robot1", 5));
            assertThat(store.homeOf("robot1")).contains(dir.resolve("robots.xml"));
        }
        assertThat(dir.resolve(".kicnp").resolve(Manifest.FILE)).doesNotExist();
    }

    @Test
    void open_whenTempFilesLackAManifest_deletesThemAndKeepsTheOldFiles() throws Exception {
        Path dir = baseDir(tmp);
        Path temp = dir.resolve("base.xml" + Compaction.TEMP_SUFFIX);
        Files.writeString(temp, "<?xml version=\"1.0\"?><KNOWLEDGEBASE><FRAME><NAME>half"); // cut mid-write

        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().require("robot1")).isEqualTo(robot("robot1", 1));
        }
        assertThat(temp).doesNotExist();
    }

    @Test
    void open_whenTheLastRecordIsTorn_cutsItOffAndKeepsEveryEarlierRecord() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(learnedUser("ann", 1));
            store.kb().add(learnedUser("bob", 1));
        }
        Path segment = journalSegments(dir).get(0);
        long intact = Files.size(segment);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(learnedUser("cid", 1));
        }
        long full = Files.size(segment);
        try (RandomAccessFile f = new RandomAccessFile(segment.toFile(), "rw")) {
            f.setLength(full - 5); // the write of cid's record was cut short
        }

        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().contains("ann")).isTrue();
            assertThat(store.kb().contains("bob")).isTrue();
            assertThat(store.kb().contains("cid")).isFalse();
            store.kb().add(learnedUser("dan", 1)); // appends after the cut, not after the garbage
        }
        assertThat(Files.size(segment)).isGreaterThan(intact);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().contains("dan")).isTrue();
            assertThat(store.journalRecords()).isEqualTo(3);
        }
    }

    @Test
    void open_whenTheLastRecordFailsItsChecksum_cutsItOff() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(learnedUser("ann", 1));
            store.kb().add(learnedUser("bob", 1));
        }
        Path segment = journalSegments(dir).get(0);
        try (RandomAccessFile f = new RandomAccessFile(segment.toFile(), "rw")) {
            f.seek(f.length() - 20);
            int b = f.read();
            f.seek(f.length() - 20);
            f.write(b ^ 0x5A);
        }

        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().contains("ann")).isTrue();
            assertThat(store.kb().contains("bob")).isFalse();
        }
    }

    @Test
    void open_whenAnOlderSegmentIsDamaged_refusesRatherThanSkippingChanges() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(learnedUser("ann", 1));
        }
        Path first = journalSegments(dir).get(0);
        Files.writeString(dir.resolve(".kicnp/journal-00000000000000000002"), "");
        try (RandomAccessFile f = new RandomAccessFile(first.toFile(), "rw")) {
            f.seek(0);
            f.write(0);
        }

        assertThatThrownBy(() -> KnowledgeStore.open(dir, QUIET)).isInstanceOf(StoreException.class)
                .hasMessageContaining("journal-00000000000000000001").hasMessageContaining("bad magic")
                .hasMessageContaining("newer segments follow");
        KnowledgeStore.open(dir.resolveSibling("other"), QUIET).close(); // the failed open released its lock
        assertThatThrownBy(() -> KnowledgeStore.open(dir, QUIET)).hasMessageNotContaining("already open");
    }

    @Test
    void open_whenTheJournalRepeatsWhatTheFilesHold_changesNothing() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(learnedUser("ann", 1));
            store.kb().replace(robot("robot1", 3));
        }
        Path segment = journalSegments(dir).get(0);
        byte[] journal = Files.readAllBytes(segment);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.compact();
        }
        // A crash between the renames and the deletion of the folded segment leaves it behind.
        Files.write(segment, journal);

        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().require("robot1")).isEqualTo(robot("robot1", 3));
            assertThat(store.kb().require("ann")).isEqualTo(learnedUser("ann", 1));
            assertThat(store.kb().size()).isEqualTo(4);
        }
    }

    @Test
    void compact_whenAFileCannotBeWritten_failsKeepsEveryChangeAndSucceedsLater() throws Exception {
        Path dir = baseDir(tmp);
        // A directory where the temporary file of learned.xml must go: that write fails.
        Path blocker = Files.createDirectories(dir.resolve("learned.xml" + Compaction.TEMP_SUFFIX).resolve("x"));
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(learnedUser("ann", 1));
            store.kb().replace(robot("robot1", 4));

            assertThatThrownBy(store::compact).isInstanceOf(StoreException.class)
                    .hasMessageContaining("the journal still holds every change");
            store.kb().add(learnedUser("bob", 1));
            assertThat(dir.resolve("learned.xml")).doesNotExist();

            Files.delete(blocker);
            Files.delete(blocker.getParent());
            store.compact();
            assertThat(StoreFixtures.namesIn(dir.resolve("learned.xml"))).containsExactly("ann", "bob");
            assertThat(StoreFixtures.xmlOnly(dir).get("robot1")).isEqualTo(robot("robot1", 4));
            assertThat(journalSegments(dir)).hasSize(1);
        }
    }
    /**
     * A crash can tear only the last record of the newest segment. A damaged record with intact ones after it is
     * something else (a bad disk, an edit): cutting there would drop acknowledged changes for good.
     */
    @Test
    void open_whenARecordOfTheNewestSegmentIsDamagedButIntactOnesFollow_refusesAndKeepsTheJournal() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(learnedUser("ann", 1));
            store.kb().add(learnedUser("bob", 1));
            store.kb().add(learnedUser("cid", 1));
        }
        Path segment = journalSegments(dir).get(0);
        try (RandomAccessFile f = new RandomAccessFile(segment.toFile(), "rw")) {
            f.seek(Journal.HEADER + 20); // inside ann's payload
            int b = f.read();
            f.seek(Journal.HEADER + 20);
            f.write(b ^ 0x5A);
        }
        byte[] damaged = Files.readAllBytes(segment);

        assertThatThrownBy(() -> KnowledgeStore.open(dir, QUIET)).isInstanceOf(StoreException.class)
                .hasMessageContaining("journal-00000000000000000001").hasMessageContaining("at byte 0")
                .hasMessageContaining("checksum mismatch").hasMessageContaining("intact record");
        assertThat(Files.readAllBytes(segment)).as("the journal is kept for a person to look at").isEqualTo(damaged);
    }
    /**
     * A compaction that cannot start a new journal segment (no file descriptor or directory entry to spare) must not
     * take the journal down with it: changes go on into the current segment, and a later compaction works.
     */
    @Test
    void compact_whenTheNewSegmentCannotBeCreated_failsAndChangesGoOnIntoTheCurrentOne() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(learnedUser("ann", 1));
            Path blocker = Files.createDirectories(dir.resolve(".kicnp/journal-00000000000000000002"));

            assertThatThrownBy(store::compact).isInstanceOf(StoreException.class)
                    .hasMessageContaining("Could not start a new journal segment");
            store.kb().add(learnedUser("bob", 1));

            Files.delete(blocker);
            store.compact();
            assertThat(StoreFixtures.namesIn(dir.resolve("learned.xml"))).containsExactly("ann", "bob");
        }
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().contains("bob")).isTrue();
        }
    }
    /**
     * Edited by hand after a crash, the files no longer take the journal: the message must say where the frames it
     * names are written, the hand-written one at its file and line, the other at its journal record.
     */
    @Test
    void open_whenAHandEditConflictsWithTheJournal_namesTheFileAndLineAndTheJournalRecord() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(org.kicnp.core.Frame.classFrame("Gadget").build());
            store.compact();
            store.kb().remove("Gadget"); // in the journal only: the process dies before it is folded
        }
        Files.writeString(dir.resolve("mine.xml"), """
                <?xml version="1.0" encoding="UTF-8"?>
                <KNOWLEDGEBASE>
                  <FRAME>
                    <NAME>Phone</NAME>
                    <ISA>Gadget</ISA>
                  </FRAME>
                </KNOWLEDGEBASE>
                """);

        assertThatThrownBy(() -> KnowledgeStore.open(dir, QUIET)).isInstanceOf(StoreException.class)
                .hasMessageContaining("'Gadget' cannot be removed")
                .hasMessageContaining("'Phone' at " + dir.resolve("mine.xml") + ":3:")
                .hasMessageContaining("Where they are: 'Gadget' changed by the journal record "
                        + "journal-00000000000000000002 at byte 0");
    }
}
