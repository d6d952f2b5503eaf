package org.kicnp.core.store;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.SortedMap;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;

/**
 * The process {@link KnowledgeStoreCrashTest} kills. Opens the store (default options: fsync on, background
 * compaction) with a small compaction threshold and makes {@link CrashWorkload} changes forever, printing
 * {@code ACK <op>} only after each change returned: a promise that the change is durable.
 *
 * <p>Arguments: directory, seed, first operation number, compaction threshold in records.
 */
public final class CrashChild {
    private CrashChild() {
    }

    public static void main(String[] args) {
        Path dir = Path.of(args[0]);
        Random rnd = new Random(Long.parseLong(args[1]));
        long op = Long.parseLong(args[2]);
        int threshold = Integer.parseInt(args[3]);
        PrintStream out = System.out; // this is the child's protocol with the parent test, not logging
        KnowledgeStore store = KnowledgeStore.open(dir, StoreOptions.defaults().withCompactAfterRecords(threshold));
        KnowledgeBase kb = store.kb();
        SortedMap<String, Frame> durable = CrashWorkload.durable(kb);
        out.println("OPEN");
        out.flush();
        while (true) {
            List<Change> changes = CrashWorkload.next(rnd, op, durable);
            kb.apply(changes);
            CrashWorkload.apply(durable, changes);
            out.println("ACK " + op + " OK");
            out.flush();
            op++;
        }
    }
}
