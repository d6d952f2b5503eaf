package org.kicnp.core;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A batch of changes folded into the state it would leave: for each touched name, the frame after the batch or
 * null where the batch removes it, in the order names were first touched.
 */
final class Batch {
    private final Map<String, Frame> staged;
    private final Map<String, List<String>> stagedChildren = new HashMap<>();

    private Batch(int size) {
        staged = LinkedHashMap.newLinkedHashMap(size);
    }

    static Batch stage(List<? extends Change> changes, Map<String, Node> nodes) {
        Batch b = new Batch(changes.size());
        List<Problem> problems = new ArrayList<>();
        for (Change c : changes) {
            String name = c.name();
            Frame already = b.staged.get(name);
            // Staged as null means removed earlier in the batch; otherwise the knowledge base decides.
            boolean exists = already != null || nodes.containsKey(name) && !b.staged.containsKey(name);
            switch (c) {
                case Change.Add a -> {
                    if (exists) {
                        problems.add(Problem.of(name, "A frame named '" + name + "' already exists."));
                    } else {
                        b.staged.put(name, a.frame());
                    }
                }
                case Change.Replace r -> {
                    if (!exists) {
                        problems.add(Problem.of(name, "There is no frame named '" + name + "' to replace."));
                        continue;
                    }
                    Node n = nodes.get(name);
                    if (r.expectedRevision() != Change.ANY_REVISION && n != null && n.revision != r.expectedRevision()) {
                        throw new StaleRevisionException(name, r.expectedRevision(), n.revision);
                    }
                    b.staged.put(name, r.frame());
                }
                case Change.Put p -> b.staged.put(name, p.frame());
                case Change.Remove rm -> {
                    if (!exists) {
                        problems.add(Problem.of(name, "There is no frame named '" + name + "' to remove."));
                    } else {
                        b.staged.put(name, null);
                    }
                }
            }
        }
        if (!problems.isEmpty()) {
            throw new BatchRejectedException(problems);
        }
        b.staged.forEach((name, f) -> {
            if (f != null && f.parent().isPresent()) {
                b.stagedChildren.computeIfAbsent(f.parent().get(), k -> new ArrayList<>()).add(name);
            }
        });
        return b;
    }

    Map<String, Frame> staged() {
        return staged;
    }

    Map<String, List<String>> stagedChildren() {
        return stagedChildren;
    }

    /** What the batch does, frame by frame; a put that changes nothing makes no event. */
    List<FrameEvent> events(Map<String, Node> nodes) {
        List<FrameEvent> events = new ArrayList<>(staged.size());
        staged.forEach((name, after) -> {
            Node n = nodes.get(name);
            Frame before = n == null ? null : n.frame;
            if (before == null && after != null) {
                events.add(new FrameEvent.Added(after));
            } else if (before != null && after == null) {
                events.add(new FrameEvent.Removed(before));
            } else if (before != null && !before.equals(after)) {
                events.add(new FrameEvent.Replaced(before, after));
            }
        });
        return events;
    }
}
