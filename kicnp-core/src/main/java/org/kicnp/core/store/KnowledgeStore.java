package org.kicnp.core.store;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.ReentrantLock;
import java.util.stream.Stream;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameEvent;
import org.kicnp.core.KnowledgeBase;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A knowledge base kept in a directory: the paper's XML files plus a journal in {@code .kicnp/}. The store is the
 * knowledge base's {@link org.kicnp.core.CommitLog}: each committed batch of durable changes is one journal record,
 * forced to disk before the knowledge base shows the change, so a change the API acknowledged survives a crash.
 * Compaction folds the journal into the XML files from time to time (see {@link Compaction}); opening the store
 * finishes an interrupted compaction, loads the XML files and replays the journal on top.
 *
 * <p>Each durable frame has a home file: the one it was loaded from, or {@value FileLayout#LEARNED} for a new
 * learned frame and {@value FileLayout#EDITS} for any other new frame. Runtime frames are never written.
 */
public final class KnowledgeStore implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(KnowledgeStore.class);
    /** The store's own directory inside the knowledge directory. */
    public static final String META_DIR = ".kicnp";

    private final Path dir;
    private final Path metaDir;
    private final StoreOptions options;
    private final Disk disk;
    private final ReentrantLock lock = new ReentrantLock();
    private final ReentrantLock compaction = new ReentrantLock();
    private final AtomicBoolean compactionQueued = new AtomicBoolean();
    private final FileLayout layout = new FileLayout();
    private final ExecutorService compactor;
    private final DirectoryLock dirLock;
    private Journal journal;
    private KnowledgeBase kb;
    private volatile boolean recovering = true;
    private boolean closed;
    private boolean lastCompactionFailed;

    private KnowledgeStore(Path dir, StoreOptions options, Disk disk, DirectoryLock dirLock) {
        this.dir = dir;
        this.metaDir = dir.resolve(META_DIR);
        this.options = options;
        this.disk = disk;
        this.dirLock = dirLock;
        this.compactor = options.compactInBackground() ? Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "kicnp-store-compactor");
            t.setDaemon(true);
            return t;
        }) : null;
    }

    /**
     * Whether opening {@code dir} would find more than its XML files: a journal segment that holds something, or an
     * interrupted compaction to finish (an unreadable segment counts, so that the open says what is wrong with it).
     * Reads the directory only; opens nothing.
     */
    public static boolean hasPendingChanges(Path dir) {
        Path meta = dir.resolve(META_DIR);
        if (!Files.isDirectory(meta)) {
            return false;
        }
        try (Stream<Path> files = Files.list(meta)) {
            return files.anyMatch(p -> {
                String name = p.getFileName().toString();
                try {
                    return name.equals(Manifest.FILE) || Journal.isSegment(name) && Files.size(p) > 0;
                } catch (IOException e) {
                    return true;
                }
            });
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Opens (creating if needed) the knowledge directory with the {@link StoreOptions#defaults() default options}. */
    public static KnowledgeStore open(Path dir) {
        return open(dir, StoreOptions.defaults());
    }

    /**
     * Opens (creating if needed) the knowledge directory: finishes an interrupted compaction, loads every
     * {@code *.xml} file below {@code dir} (skipping hidden files and directories, such as {@code .kicnp}), replays
     * the journal and returns the store, whose {@link #kb()} then holds every acknowledged durable change.
     *
     * @throws StoreException when the directory cannot be read or is damaged beyond what a crash explains, or is
     *     open in another store
     * @throws org.kicnp.core.KnowledgeException when an XML file or the replayed journal breaks the frame model
     */
    public static KnowledgeStore open(Path dir, StoreOptions options) {
        requireNonNull(dir, "dir");
        requireNonNull(options, "options");
        Path absolute = dir.toAbsolutePath().normalize();
        Disk disk = new Disk(options.fsync());
        DirectoryLock dirLock = DirectoryLock.acquire(absolute.resolve(META_DIR), disk);
        KnowledgeStore store = new KnowledgeStore(absolute, options, disk, dirLock);
        try {
            store.kb = KnowledgeBase.create(store::append);
            store.journal = new Recovery(store.dir, store.metaDir, store.disk, store.layout).run(store.kb);
            store.recovering = false;
            if (store.journal.pendingRecords() >= options.compactAfterRecords()
                    || store.journal.pendingBytes() >= options.compactAfterBytes()) {
                store.scheduleCompaction();
            }
            return store;
        } catch (IOException e) {
            store.abandon();
            throw new StoreException("Could not open the knowledge store in '" + absolute + "': " + e.getMessage(), e);
        } catch (RuntimeException e) {
            store.abandon();
            throw e;
        }
    }

    /** The knowledge base this store keeps durable. */
    public KnowledgeBase kb() {
        return kb;
    }

    /** The knowledge directory. */
    public Path dir() {
        return dir;
    }

    /** The XML file a durable frame lives in (or will, at the next compaction). Empty for runtime or unknown frames. */
    public Optional<Path> homeOf(String frameName) {
        lock.lock();
        try {
            return layout.homeOf(frameName).map(dir::resolve);
        } finally {
            lock.unlock();
        }
    }

    /** Number of journal records not yet being folded into the XML files. */
    public int journalRecords() {
        lock.lock();
        try {
            return journal.pendingRecords();
        } finally {
            lock.unlock();
        }
    }

    /** The commit log of {@link #kb()}: makes the batch durable before the knowledge base shows it. */
    private void append(long version, List<FrameEvent> events) {
        if (recovering) {
            return; // loading the XML files and replaying the journal: already on disk
        }
        JournalRecord record = JournalRecord.of(version, events);
        byte[] payload = JournalCodec.encode(record);
        boolean compactNow;
        lock.lock();
        try {
            ensureOpen();
            journal.append(payload);
            layout.apply(record);
            compactNow = journal.pendingRecords() >= options.compactAfterRecords()
                    || journal.pendingBytes() >= options.compactAfterBytes();
        } catch (IOException e) {
            throw new StoreException("Could not write the journal of '" + dir + "': " + e.getMessage(), e);
        } finally {
            lock.unlock();
        }
        if (compactNow) {
            scheduleCompaction();
        }
    }

    private void scheduleCompaction() {
        if (compactor == null) {
            compactQuietly(); // the record is durable: a failed compaction must not fail the change
            return;
        }
        if (compactionQueued.compareAndSet(false, true)) {
            try {
                compactor.execute(() -> {
                    compactionQueued.set(false);
                    compactQuietly();
                });
            } catch (RejectedExecutionException closing) {
                compactionQueued.set(false);
            }
        }
    }

    private void compactQuietly() {
        try {
            compact();
        } catch (RuntimeException e) {
            LOG.error("Compaction of the knowledge store in '{}' failed; the journal still holds every change", dir, e);
        }
    }

    /**
     * Folds the journal into the XML files now: rewrites every file whose frames changed (deleting those left
     * empty) crash-safely, then drops the folded journal segments. Changes go on meanwhile, into a new segment.
     *
     * @throws StoreException when a file cannot be written; nothing is lost, the journal still holds it all
     */
    public void compact() {
        compaction.lock();
        try {
            Map<Path, List<Frame>> contents;
            List<Path> folded;
            lock.lock();
            try {
                ensureOpen();
                if (journal.pendingRecords() == 0 && !layout.hasDirtyFiles() && !lastCompactionFailed) {
                    return;
                }
                folded = journal.roll();
                contents = layout.takeDirty();
            } catch (IOException e) {
                throw new StoreException("Could not start a new journal segment in '" + metaDir + "': "
                        + e.getMessage(), e);
            } finally {
                lock.unlock();
            }
            fold(contents, folded);
        } finally {
            compaction.unlock();
        }
    }

    private void fold(Map<Path, List<Frame>> contents, List<Path> folded) {
        try {
            if (lastCompactionFailed) {
                Recovery.finishInterruptedCompaction(dir, metaDir, disk);
            }
            Compaction.write(dir, metaDir, contents, disk);
            lock.lock();
            try {
                journal.delete(folded);
            } finally {
                lock.unlock();
            }
            Manifest.remove(metaDir, disk);
            lastCompactionFailed = false;
            LOG.debug("Compacted {} file(s) of '{}', dropping {} journal segment(s)", contents.size(), dir,
                    folded.size());
        } catch (IOException | RuntimeException e) {
            lastCompactionFailed = true;
            lock.lock();
            try {
                layout.markDirty(contents.keySet());
            } finally {
                lock.unlock();
            }
            throw new StoreException("Compaction of the knowledge store in '" + dir + "' failed; the journal still "
                    + "holds every change: " + e.getMessage(), e);
        }
    }

    /**
     * Compacts (unless the options say not to) and releases the directory. The knowledge base stays readable, but
     * a durable change after close fails.
     */
    @Override
    public void close() {
        lock.lock();
        try {
            if (closed) {
                return;
            }
        } finally {
            lock.unlock();
        }
        if (compactor != null) {
            compactor.shutdown();
            try {
                compactor.awaitTermination(1, TimeUnit.MINUTES);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        if (options.compactOnClose()) {
            try {
                compact();
            } catch (StoreException e) {
                LOG.warn("Could not compact '{}' on close; the journal keeps the changes: {}", dir, e.getMessage());
            }
        }
        lock.lock();
        try {
            if (closed) {
                return;
            }
            closed = true;
            journal.close();
        } catch (IOException e) {
            LOG.warn("Could not close the journal of '{}': {}", dir, e.getMessage());
        } finally {
            lock.unlock();
            dirLock.release();
        }
    }

    private void ensureOpen() {
        if (closed) {
            throw new StoreException("The knowledge store in '" + dir + "' is closed.");
        }
    }

    /** Releases what a failed open took. */
    private void abandon() {
        closed = true;
        if (compactor != null) {
            compactor.shutdownNow();
        }
        try {
            if (journal != null) {
                journal.close();
            }
        } catch (IOException e) {
            LOG.debug("Closing the journal of an abandoned open failed", e);
        }
        dirLock.release();
    }
}
