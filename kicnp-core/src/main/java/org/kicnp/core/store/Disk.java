package org.kicnp.core.store;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/** Forces file contents and directory entries to the storage device, or does nothing when fsync is off. */
final class Disk {
    private final boolean fsync;

    Disk(boolean fsync) {
        this.fsync = fsync;
    }

    /** Forces an open file's contents and metadata to the device. */
    void force(FileChannel channel) throws IOException {
        if (fsync) {
            channel.force(true);
        }
    }

    /**
     * Forces an open file's contents, and the metadata needed to read them back such as its size (fdatasync), to the
     * device: enough for a journal append, and cheaper than {@link #force}.
     */
    void forceData(FileChannel channel) throws IOException {
        if (fsync) {
            channel.force(false);
        }
    }

    /** Forces a directory's entries, so that a create, rename or delete in it survives a power cut. */
    void syncDirectory(Path dir) throws IOException {
        if (fsync) {
            try (FileChannel ch = FileChannel.open(dir, StandardOpenOption.READ)) {
                ch.force(true);
            }
        }
    }
}
