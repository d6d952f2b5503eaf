package org.kicnp.core.store;

import static org.kicnp.core.store.StoreFixtures.learnedUser;
import static org.kicnp.core.store.StoreFixtures.robot;
import static org.kicnp.core.store.StoreFixtures.user;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.SortedMap;
import java.util.TreeMap;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;

/**
 * The changes the crash child makes, as a pure function of a random stream, the operation number and the durable
 * frames: the parent test replays it to know exactly what each acknowledged operation did. A mix of learned adds,
 * declared adds, replaces, removes, edits of a frame from {@code base.xml}, two-change batches and runtime frames
 * (which must never survive a restart).
 */
final class CrashWorkload {
    private static final int MAX_FRAMES = 40;

    private CrashWorkload() {
    }

    /** The durable frames of a knowledge base, by name. */
    static SortedMap<String, Frame> durable(KnowledgeBase kb) {
        SortedMap<String, Frame> out = new TreeMap<>();
        kb.frames().stream().filter(f -> f.provenance().durable()).forEach(f -> out.put(f.name(), f));
        return out;
    }

    /** The batch of operation {@code op} given the durable frames before it. */
    static List<Change> next(Random rnd, long op, SortedMap<String, Frame> durable) {
        List<String> made = durable.keySet().stream().filter(n -> n.startsWith("u") || n.startsWith("e")).toList();
        int roll = rnd.nextInt(100);
        if (made.size() >= MAX_FRAMES && roll < 45) {
            roll = 70; // keep the knowledge base small: remove instead of add
        }
        String some = made.isEmpty() ? null : made.get(rnd.nextInt(made.size()));
        if (some == null && roll >= 45 && roll < 80) {
            roll = 0;
        }
        if (roll < 35) {
            return List.of(new Change.Add(learnedUser("u" + op, op)));
        } else if (roll < 45) {
            return List.of(new Change.Add(user("e" + op, "Edited " + op, op, Provenance.DECLARED)));
        } else if (roll < 65) {
            Frame old = durable.get(some);
            return List.of(new Change.Replace(user(some, "Renamed " + op, op, old.provenance())));
        } else if (roll < 80) {
            return List.of(new Change.Remove(some));
        } else if (roll < 87) {
            return List.of(new Change.Replace(robot("robot1", op)));
        } else if (roll < 93) {
            List<Change> batch = new ArrayList<>();
            batch.add(new Change.Add(learnedUser("u" + op, op)));
            if (some != null) {
                batch.add(new Change.Remove(some));
            }
            return batch;
        } else {
            return List.of(new Change.Add(user("r" + op, "Stimulus " + op, op, Provenance.RUNTIME)));
        }
    }

    /** What a committed batch does to the durable frames. */
    static void apply(SortedMap<String, Frame> durable, List<Change> changes) {
        for (Change c : changes) {
            switch (c) {
                case Change.Add a -> putOrDrop(durable, a.frame());
                case Change.Replace r -> putOrDrop(durable, r.frame());
                case Change.Put p -> putOrDrop(durable, p.frame());
                case Change.Remove r -> durable.remove(r.name());
            }
        }
    }

    private static void putOrDrop(SortedMap<String, Frame> durable, Frame f) {
        if (f.provenance().durable()) {
            durable.put(f.name(), f);
        } else {
            durable.remove(f.name());
        }
    }
}
