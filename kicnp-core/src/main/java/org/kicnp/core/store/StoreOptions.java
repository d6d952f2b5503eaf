package org.kicnp.core.store;

/**
 * How a {@link KnowledgeStore} trades speed for safety and when it compacts.
 *
 * @param fsync whether writes are forced to the storage device; turn it off only in tests that do not cut power
 *     (a killed process loses nothing that reached the operating system either way)
 * @param compactAfterRecords compact once the journal holds this many records since the last compaction
 * @param compactAfterBytes compact once the journal holds this many bytes since the last compaction
 * @param compactInBackground compact on a store thread rather than in the thread whose change crossed a threshold
 * @param compactOnClose fold the journal into the XML files when the store closes, so that the files alone are
 *     up to date for a person editing them while the server is down
 */
public record StoreOptions(boolean fsync, int compactAfterRecords, long compactAfterBytes,
                           boolean compactInBackground, boolean compactOnClose) {

    public StoreOptions {
        if (compactAfterRecords < 1) {
            throw new IllegalArgumentException("compactAfterRecords must be at least 1, not " + compactAfterRecords + ".");
        }
        if (compactAfterBytes < 1) {
            throw new IllegalArgumentException("compactAfterBytes must be at least 1, not " + compactAfterBytes + ".");
        }
    }

    /** Safe defaults: fsync on, compaction in the background after 1,000 records or 8 MiB, compaction on close. */
    public static StoreOptions defaults() {
        return new StoreOptions(true, 1_000, 8L << 20, true, true);
    }

    public StoreOptions withFsync(boolean on) {
        return new StoreOptions(on, compactAfterRecords, compactAfterBytes, compactInBackground, compactOnClose);
    }

    public StoreOptions withCompactAfterRecords(int records) {
        return new StoreOptions(fsync, records, compactAfterBytes, compactInBackground, compactOnClose);
    }

    public StoreOptions withCompactAfterBytes(long bytes) {
        return new StoreOptions(fsync, compactAfterRecords, bytes, compactInBackground, compactOnClose);
    }

    public StoreOptions withCompactInBackground(boolean on) {
        return new StoreOptions(fsync, compactAfterRecords, compactAfterBytes, on, compactOnClose);
    }

    public StoreOptions withCompactOnClose(boolean on) {
        return new StoreOptions(fsync, compactAfterRecords, compactAfterBytes, compactInBackground, on);
    }
}
