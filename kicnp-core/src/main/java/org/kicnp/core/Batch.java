package org.kicnp.core;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A batch of changes folded into the state it would leave: for each touched name, the frame after the batch or
 * null where the batch removes it, in the order names were first touched. Also notes whether the batch leaves every
 * class as it was (it touches instances only), which lets validation use what the knowledge base knows of its classes.
 */
final class Batch {
    /** Name → frame after the batch (null: removed); a singleton map for a batch of one change, the usual case. */
    private Map<String, Frame> staged;
    private final boolean single;
    private boolean classesUnchanged = true;

    private Batch(int size) {
        single = size == 1;
        staged = single ? Map.of() : LinkedHashMap.newLinkedHashMap(size);
    }

    static Batch stage(List<? extends Change> changes, NodeIndex nodes) {
        Batch b = new Batch(changes.size());
        List<Problem> problems = null;
        for (Change c : changes) {
            String name = c.name();
            Node n = nodes.get(name);
            Frame already = b.staged.get(name);
            // Staged as null means removed earlier in the batch; otherwise the knowledge base decides.
            boolean exists = already != null || n != null && !b.staged.containsKey(name);
            if (n != null && n.frame.isClass()) {
                b.classesUnchanged = false;
            }
            String problem = null;
            switch (c) {
                case Change.Add a -> {
                    if (exists) {
                        problem = "A frame named '" + name + "' already exists.";
                    } else {
                        b.stage(name, a.frame());
                    }
                }
                case Change.Replace r -> {
                    if (!exists) {
                        problem = "There is no frame named '" + name + "' to replace.";
                    } else {
                        if (r.expectedRevision() != Change.ANY_REVISION && n != null && n.revision != r.expectedRevision()) {
                            throw new StaleRevisionException(name, r.expectedRevision(), n.revision);
                        }
                        b.stage(name, r.frame());
                    }
                }
                case Change.Put p -> b.stage(name, p.frame());
                case Change.Remove rm -> {
                    if (!exists) {
                        problem = "There is no frame named '" + name + "' to remove.";
                    } else {
                        if (rm.expectedRevision() != Change.ANY_REVISION && n != null && n.revision != rm.expectedRevision()) {
                            throw new StaleRevisionException(name, rm.expectedRevision(), n.revision);
                        }
                        b.stage(name, null);
                    }
                }
            }
            if (problem != null) {
                if (problems == null) {
                    problems = new ArrayList<>();
                }
                problems.add(Problem.of(name, problem));
            }
        }
        if (problems != null) {
            throw new BatchRejectedException(problems);
        }
        return b;
    }

    private void stage(String name, Frame after) {
        if (single) {
            staged = Collections.singletonMap(name, after); // a batch of one change stages at most once
        } else {
            staged.put(name, after);
        }
        if (after != null && after.isClass()) {
            classesUnchanged = false;
        }
    }

    Map<String, Frame> staged() {
        return staged;
    }

    /** Whether no frame the batch touches is a class, before or after: the IS-A hierarchy of classes stays as it is. */
    boolean classesUnchanged() {
        return classesUnchanged;
    }

    /** What the batch does, frame by frame; a put that changes nothing makes no event. */
    List<FrameEvent> events(NodeIndex nodes) {
        if (single) {
            if (staged.isEmpty()) {
                return List.of();
            }
            Map.Entry<String, Frame> only = staged.entrySet().iterator().next();
            FrameEvent e = event(nodes.get(only.getKey()), only.getValue());
            return e == null ? List.of() : List.of(e);
        }
        List<FrameEvent> events = new ArrayList<>(staged.size());
        for (Map.Entry<String, Frame> s : staged.entrySet()) {
            FrameEvent e = event(nodes.get(s.getKey()), s.getValue());
            if (e != null) {
                events.add(e);
            }
        }
        return events;
    }

    /** The event of one staged frame over the node it had before (null: none), or null when nothing changes. */
    private static FrameEvent event(Node n, Frame after) {
        Frame before = n == null ? null : n.frame;
        if (before == null && after != null) {
            return new FrameEvent.Added(after);
        } else if (before != null && after == null) {
            return new FrameEvent.Removed(before);
        } else if (before != null && !before.equals(after)) {
            return new FrameEvent.Replaced(before, after);
        }
        return null;
    }
}
