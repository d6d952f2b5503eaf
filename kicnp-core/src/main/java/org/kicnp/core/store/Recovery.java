package org.kicnp.core.store;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Function;
import org.kicnp.core.BatchRejectedException;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Problem;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.core.xml.SourceLocation;
import org.kicnp.core.xml.SourcedFrame;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Brings a knowledge directory back to the last acknowledged state, in this order: finish the moves of an
 * interrupted compaction (its manifest), delete stray temporary files, load the XML files, replay the journal into
 * the file layout, and bring the knowledge base to the layout's frames in one validated batch. Replaying records
 * already folded into the files changes nothing, because every journal operation is a whole-frame put or a delete.
 */
final class Recovery {
    private static final Logger LOG = LoggerFactory.getLogger(Recovery.class);

    private final Path dir;
    private final Path metaDir;
    private final Disk disk;
    private final FileLayout layout;
    /** Where each frame read from the XML files is written, to name it in a message. */
    private final Map<String, SourceLocation> inFiles = new HashMap<>();
    /** The journal record that last put or deleted each name, to name it in a message. */
    private final Map<String, String> inJournal = new HashMap<>();

    Recovery(Path dir, Path metaDir, Disk disk, FileLayout layout) {
        this.dir = dir;
        this.metaDir = metaDir;
        this.disk = disk;
        this.layout = layout;
    }

    /**
     * Recovers into {@code kb}, an empty knowledge base whose commit log ignores what recovery applies (it is on
     * disk already), and returns the journal, ready for appends.
     */
    Journal run(KnowledgeBase kb) throws IOException {
        finishInterruptedCompaction(dir, metaDir, disk);
        List<Path> files = xmlFiles();
        load(kb, files);
        List<Journal.Entry> entries = new ArrayList<>();
        Journal journal = Journal.open(metaDir, disk, entries);
        int changed;
        try {
            // A record was written against the frames the records before it left, not against the files alone.
            Function<String, Optional<Frame>> above = name -> layout.frame(name).or(() -> kb.frame(name));
            for (Journal.Entry e : entries) {
                JournalRecord record = JournalCodec.decode(e.payload(), e.where(), kb, above);
                record.ops().forEach(op -> inJournal.put(op.name(), e.where()));
                layout.apply(record);
            }
            changed = reconcile(kb);
        } catch (RuntimeException e) {
            journal.close();
            throw e;
        }
        LOG.info("Opened knowledge store '{}': {} frames from {} XML file(s), {} journal record(s) replayed ({} frame(s) "
                + "changed by them)", dir, kb.size(), files.size(), entries.size(), changed);
        return journal;
    }

    /** Completes the moves of a compaction whose manifest survived, and removes what an unfinished one left. */
    static void finishInterruptedCompaction(Path dir, Path metaDir, Disk disk) throws IOException {
        Optional<Manifest> manifest = Manifest.read(metaDir);
        if (manifest.isPresent()) {
            LOG.info("Finishing an interrupted compaction in '{}' ({} file move(s))", dir,
                    manifest.get().entries().size());
            manifest.get().complete(dir, disk);
            Manifest.remove(metaDir, disk);
        }
        Compaction.deleteStrayTemps(dir, metaDir);
    }

    /** Every {@code *.xml} file below the directory, by the XML loader's rules (hidden files and directories skipped). */
    private List<Path> xmlFiles() {
        return KnowledgeLoader.expand(List.of(dir));
    }

    private void load(KnowledgeBase kb, List<Path> files) {
        Map<String, Path> homeBySource = new HashMap<>();
        for (Path f : files) {
            Path relative = dir.relativize(f);
            layout.knownFile(relative);
            homeBySource.put(f.toString(), relative);
            homeBySource.put(f.toUri().toString(), relative);
            homeBySource.put(relative.toString(), relative);
        }
        if (files.isEmpty()) {
            return;
        }
        for (SourcedFrame sf : KnowledgeLoader.load(kb, files)) {
            inFiles.put(sf.frame().name(), sf.location());
            Path home = homeBySource.get(sf.location().source());
            if (home == null) {
                throw new StoreException("The XML loader named the source of frame '" + sf.frame().name() + "' as '"
                        + sf.location().source() + "', which is none of the files of '" + dir + "'.");
            }
            if (sf.frame().provenance().durable()) {
                layout.loaded(home, sf.frame()); // a RUNTIME fixture is loaded each time but never written
            }
        }
    }

    /**
     * Where the frames the problems name (their own frame, and frames quoted in the message) are written: the journal
     * record that last changed one, else its place in the XML files; empty when there is nothing to say.
     */
    private String places(List<Problem> problems) {
        Set<String> names = new LinkedHashSet<>();
        for (Problem p : problems) {
            names.add(p.frame());
            String m = p.message();
            for (int open = m.indexOf('\''); open >= 0; ) {
                int close = m.indexOf('\'', open + 1);
                if (close < 0) {
                    break;
                }
                names.add(m.substring(open + 1, close));
                open = m.indexOf('\'', close + 1);
            }
        }
        List<String> out = new ArrayList<>();
        for (String n : names) {
            if (inJournal.containsKey(n)) {
                out.add("'" + n + "' changed by the journal record " + inJournal.get(n));
            } else if (inFiles.containsKey(n)) {
                out.add("'" + n + "' at " + inFiles.get(n));
            }
        }
        return out.isEmpty() ? "" : " Where they are: " + String.join("; ", out) + ".";
    }

    /** Brings the knowledge base to the frames of the layout in one batch; returns the number of frames changed. */
    private int reconcile(KnowledgeBase kb) {
        Map<String, Frame> target = layout.frames();
        List<Change> changes = new ArrayList<>();
        for (Frame f : kb.frames()) {
            if (f.provenance().durable() && !target.containsKey(f.name())) {
                changes.add(new Change.Remove(f.name()));
            }
        }
        target.forEach((name, f) -> {
            if (!kb.frame(name).map(f::equals).orElse(false)) {
                changes.add(new Change.Put(f));
            }
        });
        if (changes.isEmpty()) {
            return 0;
        }
        try {
            kb.apply(changes);
        } catch (BatchRejectedException e) {
            throw new StoreException("The journal of '" + dir + "' does not replay onto its XML files: "
                    + e.getMessage() + places(e.problems()) + " The journal is kept unchanged; fix the XML files and "
                    + "open the store again.", e);
        }
        return changes.size();
    }
}
