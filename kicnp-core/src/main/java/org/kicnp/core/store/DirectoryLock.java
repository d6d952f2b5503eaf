package org.kicnp.core.store;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * An exclusive lock on {@code .kicnp/lock}, so that two stores never write one directory: two journals appending to
 * one segment would interleave records. The operating system drops the lock when the process dies, so a crash never
 * leaves the directory locked.
 */
final class DirectoryLock {
    private static final Logger LOG = LoggerFactory.getLogger(DirectoryLock.class);

    private final FileChannel channel;

    private DirectoryLock(FileChannel channel) {
        this.channel = channel;
    }

    /** Creates the store's own directory if needed and locks it, or refuses when another store holds it. */
    static DirectoryLock acquire(Path metaDir, Disk disk) {
        try {
            if (!Files.isDirectory(metaDir)) {
                Files.createDirectories(metaDir);
                disk.syncDirectory(metaDir.getParent());
            }
            FileChannel ch = FileChannel.open(metaDir.resolve("lock"), StandardOpenOption.CREATE,
                    StandardOpenOption.WRITE);
            FileLock lock;
            try {
                lock = ch.tryLock();
            } catch (OverlappingFileLockException e) {
                lock = null;
            }
            if (lock == null) {
                ch.close();
                throw new StoreException("The knowledge store in '" + metaDir.getParent()
                        + "' is already open, in this process or another one.");
            }
            return new DirectoryLock(ch);
        } catch (IOException e) {
            throw new StoreException("Could not lock the knowledge store in '" + metaDir.getParent() + "': "
                    + e.getMessage(), e);
        }
    }

    /** Releases the lock; harmless when already released. */
    void release() {
        try {
            channel.close(); // closing the channel releases the lock
        } catch (IOException e) {
            LOG.debug("Releasing the lock of the knowledge store failed", e);
        }
    }
}
