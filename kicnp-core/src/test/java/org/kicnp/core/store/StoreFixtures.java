package org.kicnp.core.store;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.core.xml.KnowledgeXmlWriter;

/** Frames and file helpers shared by the store tests and the crash child. */
final class StoreFixtures {
    /** Fast options for tests that do not cut power: no fsync, no automatic or background compaction. */
    static final StoreOptions QUIET = StoreOptions.defaults().withFsync(false).withCompactInBackground(false)
            .withCompactAfterRecords(1_000_000).withCompactOnClose(false);

    private StoreFixtures() {
    }

    static Frame userClass() {
        return Frame.classFrame("User").slot(Slot.builder("name", DataType.STRING).build())
                .slot(Slot.builder("visits", DataType.INTEGER).build()).build();
    }

    static Frame robotClass() {
        return Frame.classFrame("Robot").slot(Slot.builder("speed", DataType.INTEGER).build()).build();
    }

    static Frame robot(String name, long speed) {
        return Frame.instance(name, "Robot").slot(Slot.ofValue("speed", DataType.INTEGER, new Value.Int(speed)))
                .build();
    }

    static Frame user(String name, String realName, long visits, Provenance provenance) {
        return Frame.instance(name, "User").slot(Slot.ofValue("name", DataType.STRING, new Value.Str(realName)))
                .slot(Slot.ofValue("visits", DataType.INTEGER, new Value.Int(visits))).provenance(provenance).build();
    }

    static Frame learnedUser(String name, long visits) {
        return user(name, "Name of " + name, visits, Provenance.LEARNED);
    }

    /** A knowledge directory holding {@code base.xml} with the User and Robot classes and one robot. */
    static Path baseDir(Path parent) throws IOException {
        Path dir = Files.createDirectories(parent.resolve("kb"));
        KnowledgeXmlWriter.write(List.of(userClass(), robotClass(), robot("robot1", 1)), dir.resolve("base.xml"));
        return dir;
    }

    /** Every frame of the knowledge base by name. */
    static Map<String, Frame> byName(KnowledgeBase kb) {
        Map<String, Frame> out = new TreeMap<>();
        kb.frames().forEach(f -> out.put(f.name(), f));
        return out;
    }

    /** Reads the XML files of a directory, as a fresh server would without the journal. */
    static Map<String, Frame> xmlOnly(Path dir) {
        KnowledgeBase kb = KnowledgeBase.create();
        KnowledgeLoader.load(kb, List.of(dir));
        return byName(kb);
    }

    /** The frame names written in one XML file, in file order. */
    static List<String> namesIn(Path file) {
        return KnowledgeLoader.parse(List.of(file), KnowledgeBase.create()).stream().map(f -> f.frame().name()).toList();
    }

    static List<Path> journalSegments(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir.resolve(KnowledgeStore.META_DIR))) {
            return s.filter(p -> p.getFileName().toString().startsWith("journal-")).sorted().toList();
        }
    }

    /** Relative paths of every regular file in the directory tree, for checking what compaction left. */
    static Map<String, Long> files(Path dir) throws IOException {
        Map<String, Long> out = new LinkedHashMap<>();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.filter(Files::isRegularFile).sorted().toList()) {
                out.put(dir.relativize(p).toString(), Files.size(p));
            }
        }
        return out;
    }
}
