package org.kicnp.core.store;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.TreeSet;
import org.kicnp.core.Frame;

/**
 * Which XML file each durable frame lives in (its home), and the frames of every file in file order: the picture
 * of what the XML files will hold after the next compaction. A frame keeps the home it was loaded from; a new
 * frame goes to {@value #LEARNED} when it was learned and to {@value #EDITS} otherwise. A replaced frame keeps its
 * place in its file and a new one is appended, so compaction output stays stable from one run to the next.
 *
 * <p>Homes are paths relative to the store directory. Not thread-safe: the store calls it under its own lock.
 */
final class FileLayout {
    /** Home of new learned frames. */
    static final String LEARNED = "learned.xml";
    /** Home of new frames that were not learned (made in the editor or pushed by a peer). */
    static final String EDITS = "edits.xml";

    private final Map<String, Path> homes = new HashMap<>();
    private final Map<Path, LinkedHashMap<String, Frame>> files = new TreeMap<>();
    private final TreeSet<Path> dirty = new TreeSet<>();

    /** Records a frame read from an XML file; the file is as it should be, so it is not marked for rewriting. */
    void loaded(Path home, Frame frame) {
        homes.put(frame.name(), home);
        files.computeIfAbsent(home, h -> new LinkedHashMap<>()).put(frame.name(), frame);
    }

    /** Makes a file known even if it holds no frame, so that compaction can remove it once it is empty. */
    void knownFile(Path home) {
        files.computeIfAbsent(home, h -> new LinkedHashMap<>());
    }

    void apply(JournalRecord record) {
        for (JournalRecord.Op op : record.ops()) {
            switch (op) {
                case JournalRecord.Put p -> put(p.frame());
                case JournalRecord.Delete d -> delete(d.name());
            }
        }
    }

    private void put(Frame frame) {
        Path home = homes.computeIfAbsent(frame.name(), n -> Path.of(frame.learned() ? LEARNED : EDITS));
        files.computeIfAbsent(home, h -> new LinkedHashMap<>()).put(frame.name(), frame);
        dirty.add(home);
    }

    private void delete(String name) {
        Path home = homes.remove(name);
        if (home != null) {
            files.get(home).remove(name);
            dirty.add(home);
        }
    }

    Optional<Path> homeOf(String name) {
        return Optional.ofNullable(homes.get(name));
    }

    /** The durable frame of that name as the files will hold it, if there is one. */
    Optional<Frame> frame(String name) {
        Path home = homes.get(name);
        return home == null ? Optional.empty() : Optional.ofNullable(files.get(home).get(name));
    }

    /** Every durable frame, file by file in file order. */
    Map<String, Frame> frames() {
        Map<String, Frame> all = new LinkedHashMap<>();
        files.values().forEach(all::putAll);
        return all;
    }

    boolean hasDirtyFiles() {
        return !dirty.isEmpty();
    }

    /**
     * The content every changed file should now have, in file order (an empty list for a file that should go),
     * and forgets that they changed. Files that end up empty are forgotten too.
     */
    Map<Path, List<Frame>> takeDirty() {
        Map<Path, List<Frame>> out = new TreeMap<>();
        for (Path home : dirty) {
            LinkedHashMap<String, Frame> frames = files.get(home);
            out.put(home, frames == null ? List.of() : new ArrayList<>(frames.values()));
            if (frames != null && frames.isEmpty()) {
                files.remove(home);
            }
        }
        dirty.clear();
        return out;
    }

    /** Marks files to be written again, after a compaction that took them failed. */
    void markDirty(Iterable<Path> homes) {
        homes.forEach(dirty::add);
    }
}
