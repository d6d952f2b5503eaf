package org.kicnp.core.store;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.kicnp.core.store.StoreFixtures.QUIET;
import static org.kicnp.core.store.StoreFixtures.baseDir;
import static org.kicnp.core.store.StoreFixtures.byName;
import static org.kicnp.core.store.StoreFixtures.learnedUser;
import static org.kicnp.core.store.StoreFixtures.namesIn;
import static org.kicnp.core.store.StoreFixtures.robot;
import static org.kicnp.core.store.StoreFixtures.user;
import static org.kicnp.core.store.StoreFixtures.xmlOnly;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Map;
import java.util.Set;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.Provenance;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class KnowledgeStoreTest {
    @TempDir
    Path tmp;

    @Test
    void reopen_afterAddReplaceRemoveWithoutCompaction_replaysTheJournal() throws Exception {
        Path dir = baseDir(tmp);
        Map<String, Frame> before;
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            KnowledgeBase kb = store.kb();
            kb.add(learnedUser("ann", 1));
            kb.add(learnedUser("bob", 1));
            kb.replace(learnedUser("ann", 2));
            kb.replace(robot("robot1", 7));
            kb.remove("bob");
            kb.apply(List.of(new Change.Add(learnedUser("cid", 1)), new Change.Add(robot("robot2", 3))));
            before = byName(kb);
            assertThat(store.journalRecords()).isEqualTo(6);
        }
        assertThat(xmlOnly(dir)).doesNotContainKeys("ann", "cid", "robot2");

        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(byName(store.kb())).isEqualTo(before);
            assertThat(store.kb().require("robot1")).isEqualTo(robot("robot1", 7));
            assertThat(store.kb().contains("bob")).isFalse();
        }
    }

    /** The journal holds frames as XML: a learned name "" or "NULL" must not come back as no name after a restart. */
    @Test
    void reopen_learnedStringsThatPlainXmlReadsAsAbsent_comeBackAsTheyWere() throws Exception {
        Path dir = baseDir(tmp);
        Frame empty = user("ann", "", 1, Provenance.LEARNED);
        Frame spaces = user("bob", "  ", 1, Provenance.LEARNED);
        Frame nullName = user("cid", "NULL", 1, Provenance.LEARNED);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().apply(List.of(new Change.Add(empty), new Change.Add(spaces), new Change.Add(nullName)));
        }

        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET.withCompactOnClose(true))) {
            assertThat(store.kb().require("ann")).isEqualTo(empty);
            assertThat(store.kb().require("bob")).isEqualTo(spaces);
            assertThat(store.kb().require("cid")).isEqualTo(nullName);
        }
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().require("ann")).as("after compaction").isEqualTo(empty);
            assertThat(store.kb().require("cid")).isEqualTo(nullName);
        }
    }

    /** A knowledge file kept elsewhere and linked into the directory stays linked: its target is rewritten. */
    @Test
    void compact_whenAKnowledgeFileIsASymlink_rewritesItsTargetInPlaceAndKeepsTheLink() throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("kb"));
        Path shared = Files.createDirectories(tmp.resolve("shared"));
        Path target = baseDir(shared).resolve("base.xml");
        Path link = Files.createSymbolicLink(dir.resolve("base.xml"), target);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().replace(robot("robot1", 7));
            store.compact();
        }

        assertThat(link).isSymbolicLink();
        assertThat(Files.readSymbolicLink(link)).isEqualTo(target);
        assertThat(xmlOnly(shared.resolve("kb")).get("robot1")).isEqualTo(robot("robot1", 7));
        try (var leftovers = Files.list(target.getParent())) {
            assertThat(leftovers.map(p -> p.getFileName().toString())).containsExactly("base.xml");
        }
    }

    @Test
    void compact_keepsTheReplacedFilesPermissions() throws Exception {
        Path dir = baseDir(tmp);
        Path base = dir.resolve("base.xml");
        Set<PosixFilePermission> groupReadable = PosixFilePermissions.fromString("rw-r-----");
        Files.setPosixFilePermissions(base, groupReadable);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().replace(robot("robot1", 7));
            store.compact();
        }

        assertThat(xmlOnly(dir).get("robot1")).as("the file was rewritten").isEqualTo(robot("robot1", 7));
        assertThat(Files.getPosixFilePermissions(base)).isEqualTo(groupReadable);
    }

    @Test
    void compact_foldsTheJournalIntoValidXmlFilesThatReloadEqual() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            KnowledgeBase kb = store.kb();
            kb.add(learnedUser("ann", 1));
            kb.add(user("dee", "Dee", 1, Provenance.DECLARED));
            kb.replace(robot("robot1", 9));
            store.compact();

            assertThat(store.journalRecords()).isZero();
            assertThat(StoreFixtures.journalSegments(dir)).hasSize(1);
            assertThat(Files.size(StoreFixtures.journalSegments(dir).get(0))).isZero();
            assertThat(xmlOnly(dir)).isEqualTo(byName(kb));
            assertThat(namesIn(dir.resolve("base.xml"))).containsExactly("User", "Robot", "robot1");
            assertThat(namesIn(dir.resolve("learned.xml"))).containsExactly("ann");
            assertThat(namesIn(dir.resolve("edits.xml"))).containsExactly("dee");
            assertThat(StoreFixtures.files(dir).keySet()).noneMatch(f -> f.endsWith(Compaction.TEMP_SUFFIX))
                    .doesNotContain(".kicnp/" + Manifest.FILE);
        }
    }

    @Test
    void compact_twiceWithTheSameFrames_writesByteIdenticalFilesAndKeepsOrder() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(learnedUser("ann", 1));
            store.kb().add(learnedUser("bob", 1));
            store.compact();
            byte[] first = Files.readAllBytes(dir.resolve("learned.xml"));
            store.kb().replace(learnedUser("ann", 2));
            store.kb().replace(learnedUser("ann", 1));
            store.compact();
            assertThat(Files.readAllBytes(dir.resolve("learned.xml"))).isEqualTo(first);
            assertThat(namesIn(dir.resolve("learned.xml"))).containsExactly("ann", "bob");
        }
    }

    @Test
    void homeOf_learnedFrame_isLearnedXmlAndLoadedFrameKeepsItsFile() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(learnedUser("ann", 1));
            store.kb().add(user("dee", "Dee", 1, Provenance.DECLARED));
            store.kb().replace(robot("robot1", 2));

            assertThat(store.homeOf("ann")).contains(dir.resolve("learned.xml"));
            assertThat(store.homeOf("dee")).contains(dir.resolve("edits.xml"));
            assertThat(store.homeOf("robot1")).contains(dir.resolve("base.xml"));
            assertThat(store.homeOf("nobody")).isEmpty();
        }
    }

    @Test
    void runtimeFrames_areNeverWrittenAndAreGoneAfterReopen() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(user("stimulus", "Seen", 1, Provenance.RUNTIME));
            assertThat(store.journalRecords()).isZero();
            store.kb().add(learnedUser("ann", 1));
            store.kb().replace(user("ann", "Ann", 1, Provenance.RUNTIME)); // no longer durable: deleted on disk
            assertThat(store.journalRecords()).isEqualTo(2);
            assertThat(store.homeOf("ann")).isEmpty();
            store.compact();
            assertThat(Files.readString(dir.resolve("base.xml"))).doesNotContain("stimulus");
            assertThat(StoreFixtures.files(dir)).doesNotContainKey("learned.xml");
        }
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().contains("stimulus")).isFalse();
            assertThat(store.kb().contains("ann")).isFalse();
        }
    }

    @Test
    void compact_whenTheLastFrameOfAFileIsRemoved_deletesTheFile() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(learnedUser("ann", 1));
            store.compact();
            assertThat(dir.resolve("learned.xml")).exists();
            store.kb().remove("ann");
            store.compact();
            assertThat(dir.resolve("learned.xml")).doesNotExist();
        }
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().contains("ann")).isFalse();
            assertThat(store.kb().contains("robot1")).isTrue();
        }
    }

    @Test
    void close_compactsByDefaultSoThatHandEditsWhileDownAreTheBase() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET.withCompactOnClose(true))) {
            store.kb().add(learnedUser("ann", 1));
        }
        assertThat(namesIn(dir.resolve("learned.xml"))).containsExactly("ann");
        String edited = Files.readString(dir.resolve("learned.xml")).replace("Name of ann", "Ann Edited");
        Files.writeString(dir.resolve("learned.xml"), edited);

        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().value("ann", "name")).contains(new org.kicnp.core.Value.Str("Ann Edited"));
        }
    }

    @Test
    void open_whenAlreadyOpen_refusesWithTheDirectoryInTheMessage() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThatThrownBy(() -> KnowledgeStore.open(dir, QUIET)).isInstanceOf(StoreException.class)
                    .hasMessageContaining("is already open").hasMessageContaining(dir.getFileName().toString());
        }
        KnowledgeStore.open(dir, QUIET).close(); // released on close
    }

    @Test
    void change_afterClose_isRejectedAndLeavesTheKnowledgeBaseUnchanged() throws Exception {
        Path dir = baseDir(tmp);
        KnowledgeStore store = KnowledgeStore.open(dir, QUIET);
        store.close();
        store.close(); // harmless
        assertThatThrownBy(() -> store.kb().add(learnedUser("ann", 1))).isInstanceOf(KnowledgeException.class)
                .hasMessageContaining("not applied").hasMessageContaining("is closed");
        assertThat(store.kb().contains("ann")).isFalse();
    }

    @Test
    void automaticCompaction_afterThresholdRecords_foldsWithoutBeingAsked() throws Exception {
        Path dir = baseDir(tmp);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET.withCompactAfterRecords(3))) {
            store.kb().add(learnedUser("ann", 1));
            store.kb().add(learnedUser("bob", 1));
            assertThat(dir.resolve("learned.xml")).doesNotExist();
            store.kb().add(learnedUser("cid", 1));
            assertThat(store.journalRecords()).isZero();
            assertThat(namesIn(dir.resolve("learned.xml"))).containsExactly("ann", "bob", "cid");
        }
    }

    @Test
    void open_onAnEmptyDirectory_startsAnEmptyKnowledgeBase() throws Exception {
        Path dir = tmp.resolve("fresh");
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().size()).isZero();
            store.kb().add(Frame.classFrame("Thing").build());
        }
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().contains("Thing")).isTrue();
        }
    }

    @Test
    void compact_ofAFrameLoadedFromASubdirectory_rewritesThatFile() throws Exception {
        Path dir = baseDir(tmp);
        Files.createDirectories(dir.resolve("robots"));
        org.kicnp.core.xml.KnowledgeXmlWriter.write(List.of(robot("robot2", 1), robot("robot3", 1)),
                dir.resolve("robots/more.xml"));
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().replace(robot("robot2", 8));
            assertThat(store.homeOf("robot2")).contains(dir.resolve("robots/more.xml"));
            store.compact();
        }
        assertThat(namesIn(dir.resolve("robots/more.xml"))).containsExactly("robot2", "robot3");
        assertThat(xmlOnly(dir).get("robot2")).isEqualTo(robot("robot2", 8));
    }

    @Test
    void concurrentChanges_withBackgroundCompaction_allSurviveReopen() throws Exception {
        Path dir = baseDir(tmp);
        Map<String, Frame> expected;
        StoreOptions options = QUIET.withCompactInBackground(true).withCompactAfterRecords(10);
        try (KnowledgeStore store = KnowledgeStore.open(dir, options)) {
            List<Thread> writers = new java.util.ArrayList<>();
            for (int t = 0; t < 4; t++) {
                int id = t;
                writers.add(Thread.ofPlatform().start(() -> {
                    for (int i = 0; i < 150; i++) {
                        store.kb().add(learnedUser("t" + id + "_" + i, i));
                        if (i % 3 == 0) {
                            store.kb().replace(learnedUser("t" + id + "_" + i, -i));
                        }
                        if (i % 5 == 0) {
                            store.kb().remove("t" + id + "_" + i);
                        }
                    }
                }));
            }
            for (Thread w : writers) {
                w.join();
            }
            expected = byName(store.kb());
        }
        assertThat(expected).hasSize(3 + 4 * 120);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(byName(store.kb())).isEqualTo(expected);
        }
    }

    @Test
    void runtimeFixtureInAFileOfItsOwn_isLoadedEveryTimeAndNeverRewritten() throws Exception {
        Path dir = baseDir(tmp);
        String fixture = """
                <?xml version="1.0" encoding="UTF-8"?>
                <KNOWLEDGEBASE>
                  <FRAME><NAME>mouth</NAME><ISA>Robot</ISA><ISINSTANCE>TRUE</ISINSTANCE><RUNTIME>TRUE</RUNTIME></FRAME>
                </KNOWLEDGEBASE>
                """;
        Files.writeString(dir.resolve("fixtures.xml"), fixture);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().require("mouth").provenance()).isEqualTo(Provenance.RUNTIME);
            assertThat(store.homeOf("mouth")).isEmpty();
            store.kb().remove("mouth");
            store.kb().add(learnedUser("ann", 1));
            store.compact();
        }
        assertThat(Files.readString(dir.resolve("fixtures.xml"))).isEqualTo(fixture);
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().require("mouth").provenance()).isEqualTo(Provenance.RUNTIME);
            assertThat(store.kb().contains("ann")).isTrue();
        }
    }
    /**
     * A record is read back after the records before it: an instance whose LIST slot takes its item type from a
     * class that an earlier record added must come back with the same items, not fail to open.
     */
    @Test
    void reopen_instanceWhoseListItemTypeComesFromAClassAddedEarlierInTheJournal_comesBackEqual() throws Exception {
        Path dir = baseDir(tmp);
        Frame scored = Frame.classFrame("Scored").slot(org.kicnp.core.Slot.builder("marks",
                org.kicnp.core.DataType.LIST).argument("TYPE_INT").build()).build();
        Frame game = Frame.instance("game1", "Scored").slot(org.kicnp.core.Slot.ofValue("marks",
                org.kicnp.core.DataType.LIST, new org.kicnp.core.Value.Lst(List.of(new org.kicnp.core.Value.Int(3),
                        new org.kicnp.core.Value.Int(5))))).build();
        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            store.kb().add(scored);
            store.kb().add(game);
        }

        try (KnowledgeStore store = KnowledgeStore.open(dir, QUIET)) {
            assertThat(store.kb().require("game1")).isEqualTo(game);
        }
    }
}
