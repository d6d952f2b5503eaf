package org.kicnp.core.store;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.CRC32;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The append-only journal: numbered segment files {@code journal-NNNNNNNNNNNNNNNNNNNN} in the store's
 * {@code .kicnp} directory. Each entry is a 12-byte header (magic, payload length, CRC32 of length and payload)
 * followed by the payload; an append returns only after the entry is forced to disk. Compaction rolls to a new
 * segment so that appends go on while older segments are folded into the XML files, then deletes the old ones.
 *
 * <p>Not thread-safe: the {@link KnowledgeStore} calls it under its own lock.
 */
final class Journal implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(Journal.class);
    static final int MAGIC = 0x4B4A524E; // "KJRN"
    static final int HEADER = 12;
    /** Largest payload: bounds what a damaged length field can make recovery allocate. */
    static final int MAX_PAYLOAD = 256 << 20;
    private static final Pattern SEGMENT = Pattern.compile("journal-(\\d{20})");

    /** A payload read back at open, with a place to name it by in messages. */
    record Entry(byte[] payload, String where) {
    }

    private final Path dir;
    private final Disk disk;
    private final TreeMap<Long, Path> segments;
    private FileChannel active;
    private long activeSize;
    private int pendingRecords;
    private long pendingBytes;
    private boolean broken;

    private Journal(Path dir, Disk disk, TreeMap<Long, Path> segments) {
        this.dir = dir;
        this.disk = disk;
        this.segments = segments;
    }

    /**
     * Opens the journal in {@code dir}, reading every intact entry in segment order. A torn or corrupt entry at the
     * end of the newest segment was never acknowledged (its append did not return), so it is cut off with a warning.
     * Damage anywhere else is not what a crash leaves and is reported rather than guessed around.
     */
    /** Whether {@code name} is the file name of a journal segment. */
    static boolean isSegment(String name) {
        return SEGMENT.matcher(name).matches();
    }

    static Journal open(Path dir, Disk disk, List<Entry> entries) throws IOException {
        TreeMap<Long, Path> segments = new TreeMap<>();
        try (Stream<Path> files = Files.list(dir)) {
            files.forEach(p -> {
                Matcher m = SEGMENT.matcher(p.getFileName().toString());
                if (m.matches()) {
                    segments.put(Long.parseLong(m.group(1)), p);
                }
            });
        }
        Journal j = new Journal(dir, disk, segments);
        if (segments.isEmpty()) {
            j.startSegment(1);
            return j;
        }
        for (var s : segments.entrySet()) {
            boolean newest = s.getKey().equals(segments.lastKey());
            j.readSegment(s.getValue(), newest, entries);
        }
        j.active = FileChannel.open(segments.lastEntry().getValue(), StandardOpenOption.WRITE);
        j.activeSize = j.active.size();
        return j;
    }

    private void readSegment(Path segment, boolean newest, List<Entry> entries) throws IOException {
        try (FileChannel ch = FileChannel.open(segment, StandardOpenOption.READ, StandardOpenOption.WRITE)) {
            long size = ch.size();
            long pos = 0;
            String problem = null;
            while (pos < size) {
                Read r = readEntry(ch, pos, size);
                problem = r.problem();
                if (problem != null) {
                    break;
                }
                entries.add(new Entry(r.payload(), segment.getFileName() + " at byte " + pos));
                pendingRecords++;
                pendingBytes += HEADER + r.payload().length;
                pos += HEADER + r.payload().length;
            }
            if (problem == null) {
                return;
            }
            if (!newest) {
                throw new StoreException("Journal segment '" + segment + "' is damaged at byte " + pos + " (" + problem
                        + ") although newer segments follow it; a crash cannot leave that, so the store will not guess."
                        + " Restore the directory from a backup or move the segment away to drop its later changes.");
            }
            long intact = intactEntryAfter(ch, pos, size);
            if (intact >= 0) {
                throw new StoreException("Journal segment '" + segment + "' is damaged at byte " + pos + " (" + problem
                        + ") although an intact record follows at byte " + intact + "; a crash tears only the last "
                        + "record, so the store will not guess and leaves the segment as it is. Restore the directory "
                        + "from a backup, or cut the segment at byte " + pos + " to drop the changes from there on.");
            }
            LOG.warn("Journal segment '{}' ends with an incomplete entry at byte {} ({}); that change was never "
                    + "acknowledged. Cutting off {} bytes.", segment, pos, problem, size - pos);
            ch.truncate(pos);
            disk.force(ch);
        }
    }

    /**
     * Where the first intact entry after a damaged one at {@code damaged} starts, or -1. An append that a crash cut
     * short is the last one, so an intact entry after the damage means the damage is something else.
     */
    private static long intactEntryAfter(FileChannel ch, long damaged, long size) throws IOException {
        ByteBuffer chunk = ByteBuffer.allocate(1 << 16);
        for (long start = damaged + 1; start <= size - HEADER; start += chunk.capacity() - 3) {
            chunk.clear();
            readAtMost(ch, chunk, start);
            chunk.flip();
            for (int i = 0; i + 4 <= chunk.limit(); i++) {
                if (chunk.getInt(i) == MAGIC && start + i <= size - HEADER
                        && readEntry(ch, start + i, size).problem() == null) {
                    return start + i;
                }
            }
            if (chunk.limit() < chunk.capacity()) {
                break;
            }
        }
        return -1;
    }

    private static void readAtMost(FileChannel ch, ByteBuffer buf, long pos) throws IOException {
        while (buf.hasRemaining()) {
            if (ch.read(buf, pos + buf.position()) < 0) {
                return;
            }
        }
    }

    /** An entry read back: its payload, or why it is not intact. */
    private record Read(byte[] payload, String problem) {
        static Read damaged(String problem) {
            return new Read(null, problem);
        }
    }

    private static Read readEntry(FileChannel ch, long pos, long size) throws IOException {
        if (size - pos < HEADER) {
            return Read.damaged("only " + (size - pos) + " bytes of a " + HEADER + "-byte header");
        }
        ByteBuffer h = readHeader(ch, pos);
        int magic = h.getInt(0);
        int length = h.getInt(4);
        if (magic != MAGIC) {
            return Read.damaged(String.format("bad magic 0x%08X", magic));
        }
        if (length < 0 || length > MAX_PAYLOAD) {
            return Read.damaged("bad length " + length);
        }
        if (size - pos - HEADER < length) {
            return Read.damaged("payload of " + length + " bytes cut at " + (size - pos - HEADER));
        }
        ByteBuffer payload = ByteBuffer.allocate(length);
        readFully(ch, payload, pos + HEADER);
        if ((int) crc(length, payload.array()) != h.getInt(8)) {
            return Read.damaged("checksum mismatch");
        }
        return new Read(payload.array(), null);
    }

    private static ByteBuffer readHeader(FileChannel ch, long pos) throws IOException {
        ByteBuffer h = ByteBuffer.allocate(HEADER);
        readFully(ch, h, pos);
        return h;
    }

    private static void readFully(FileChannel ch, ByteBuffer buf, long pos) throws IOException {
        while (buf.hasRemaining()) {
            if (ch.read(buf, pos + buf.position()) < 0) {
                throw new IOException("Unexpected end of file.");
            }
        }
    }

    private static long crc(int length, byte[] payload) {
        CRC32 crc = new CRC32();
        crc.update(ByteBuffer.allocate(4).putInt(0, length));
        crc.update(payload);
        return crc.getValue();
    }

    /**
     * Appends one entry and forces it to disk. If the write fails the segment is cut back to where it was, so that
     * no half-written entry sits before later ones; if even that fails, the journal refuses every further append.
     */
    void append(byte[] payload) throws IOException {
        if (broken) {
            throw new StoreException("The journal in '" + dir + "' is in an unknown state after a failed write; "
                    + "reopen the store to recover it.");
        }
        if (payload.length > MAX_PAYLOAD) {
            throw new StoreException("A batch of " + payload.length + " bytes is more than the journal takes in one "
                    + "record (" + MAX_PAYLOAD + " bytes); split it into smaller batches.");
        }
        ByteBuffer buf = ByteBuffer.allocate(HEADER + payload.length);
        buf.putInt(MAGIC).putInt(payload.length).putInt((int) crc(payload.length, payload)).put(payload).flip();
        long start = activeSize;
        try {
            while (buf.hasRemaining()) {
                active.write(buf, start + buf.position());
            }
            disk.forceData(active);
        } catch (IOException e) {
            try {
                active.truncate(start);
                disk.force(active);
            } catch (IOException again) {
                broken = true;
                e.addSuppressed(again);
            }
            throw e;
        }
        activeSize = start + HEADER + payload.length;
        pendingRecords++;
        pendingBytes += HEADER + payload.length;
    }

    /** Entries written since the last roll (or all of them, just after open). */
    int pendingRecords() {
        return pendingRecords;
    }

    long pendingBytes() {
        return pendingBytes;
    }

    /** Starts a new segment for further appends and returns the older ones, which compaction will fold and delete. */
    List<Path> roll() throws IOException {
        List<Path> old = new ArrayList<>(segments.values());
        FileChannel previous = active;
        // The new segment first: if it cannot be made (no descriptor or directory entry to spare), appends go on
        // into the current one, rather than into a closed channel until the store is reopened.
        startSegment(segments.lastKey() + 1);
        try {
            previous.close();
        } catch (IOException e) {
            LOG.warn("Closing journal segment '{}' failed: {}", old.get(old.size() - 1), e.getMessage());
        }
        pendingRecords = 0;
        pendingBytes = 0;
        return old;
    }

    /** Deletes segments whose records are now in the XML files. */
    void delete(List<Path> folded) throws IOException {
        for (Path p : folded) {
            Files.deleteIfExists(p);
            segments.values().remove(p);
        }
        disk.syncDirectory(dir);
    }

    /** Creates segment {@code number} and makes it the active one; on failure the active segment stays as it was. */
    private void startSegment(long number) throws IOException {
        Path p = dir.resolve(String.format("journal-%020d", number));
        FileChannel created = FileChannel.open(p, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
        try {
            disk.syncDirectory(dir);
        } catch (IOException e) {
            created.close();
            Files.deleteIfExists(p);
            throw e;
        }
        active = created;
        activeSize = 0;
        segments.put(number, p);
    }

    @Override
    public void close() throws IOException {
        active.close();
    }
}
