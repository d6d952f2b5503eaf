package org.kicnp.core;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Objects;
import java.util.Set;

/** Applies a validated batch's events to the nodes and their derived indexes. Runs under the write lock. */
final class Indexer {
    private final NodeIndex nodes;
    /** Reused for the names each frame mentions. */
    private final List<String> refs;
    /** Frames the batch's frames refer to, at hand ({@link Node#find}); null: none. */
    private final Frame[] near;

    private Indexer(NodeIndex nodes, List<String> refs, Frame[] near) {
        this.nodes = nodes;
        this.refs = refs;
        this.near = near;
    }

    /**
     * @param refs an empty list to reuse
     * @param near frames the batch's frames may refer to, whose nodes are then reached without a look-up; or null
     */
    static void apply(NodeIndex nodes, List<FrameEvent> events, long version, List<String> refs, Frame[] near) {
        new Indexer(nodes, refs, near).apply(events, version);
    }

    /** Grows the name index once for a batch's adds (a loader's thousands of frames), not step by step. */
    private void makeRoom(List<FrameEvent> events) {
        if (events.size() < 64) {
            return;
        }
        int hashed = 0;
        int numbered = 0;
        for (FrameEvent e : events) {
            if (e instanceof FrameEvent.Added a) {
                if (NameTable.numberOf(a.frame()) < 0) {
                    hashed++;
                } else {
                    numbered++;
                }
            }
        }
        nodes.ensureRoom(hashed, numbered);
    }

    private void apply(List<FrameEvent> events, long version) {
        List<Node> attach = new ArrayList<>(events.size());
        List<Node> touched = new ArrayList<>(events.size());
        /* Nodes made by this batch cannot be members of any set yet: they are added without a membership probe. */
        Set<Node> reattached = null;
        makeRoom(events);
        for (FrameEvent e : events) {
            switch (e) {
                case FrameEvent.Removed r -> {
                    Node n = nodes.remove(r.name());
                    n.liveIn = null;
                    dropReferences(n, r.frame());
                    detach(n);
                }
                case FrameEvent.Replaced r -> {
                    Node n = nodes.get(r.name());
                    Frame before = r.before_();
                    dropReferences(n, before);
                    if (!Objects.equals(before.parentOrNull(), r.frame().parentOrNull())
                            || before.kind() != r.frame().kind()) {
                        detach(n);
                        attach.add(n);
                        if (reattached == null) {
                            reattached = Collections.newSetFromMap(new IdentityHashMap<>());
                        }
                        reattached.add(n);
                    }
                    n.frame = r.frame();
                    r.frame().node = n;
                    n.revision = version;
                    touched.add(n);
                }
                case FrameEvent.Added a -> {
                    Node n = new Node(a.frame());
                    n.revision = version;
                    nodes.put(a.name(), n);
                    n.liveIn = nodes;
                    a.frame().node = n;
                    attach.add(n);
                    touched.add(n);
                }
            }
        }
        for (Node n : attach) {
            String p = n.frame.parentOrNull();
            n.parent = p == null ? null : nodes.get(p);
            if (n.parent != null) {
                add(n.parent.children(), n, reattached);
            }
        }
        for (Node n : attach) {
            if (n.frame.isInstance()) {
                for (Node a = n.parent; a != null; a = a.parent) {
                    add(a.instances(), n, reattached);
                }
            } else if (n.instances != null && !n.instances.isEmpty()) {
                for (Node a = n.parent; a != null; a = a.parent) {
                    NodeSet above = a.instances();
                    for (Node i : n.instances) {
                        above.add(i);
                    }
                }
            }
        }
        for (Node n : touched) {
            refs.clear();
            References.collect(n.frame, refs);
            for (int i = 0, count = refs.size(); i < count; i++) {
                Node target = Node.find(nodes, refs.get(i), near);
                if (target != null && target != n) {
                    target.addReferrer(n);
                }
            }
        }
    }

    private static void add(NodeSet set, Node n, Set<Node> reattached) {
        if (reattached == null || !reattached.contains(n)) {
            set.addNew(n);
        } else {
            set.add(n);
        }
    }

    /** Takes a node out of its parent's children and its instances out of every ancestor's instance set. */
    private static void detach(Node n) {
        if (n.parent == null) {
            return;
        }
        n.parent.children.remove(n);
        for (Node a = n.parent; a != null; a = a.parent) {
            if (a.instances == null) {
                continue;
            }
            if (n.frame.isInstance()) {
                a.instances.remove(n);
            } else if (n.instances != null) {
                a.instances.removeAll(n.instances);
            }
        }
        n.parent = null;
    }

    private void dropReferences(Node n, Frame before) {
        refs.clear();
        References.collect(before, refs);
        for (int i = 0, count = refs.size(); i < count; i++) {
            Node target = nodes.get(refs.get(i));
            if (target != null) {
                target.removeReferrer(n);
            }
        }
    }
}
