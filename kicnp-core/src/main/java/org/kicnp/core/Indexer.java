package org.kicnp.core;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

/** Applies a validated batch's events to the nodes and their derived indexes. Runs under the write lock. */
final class Indexer {
    private Indexer() {
    }

    static void apply(Map<String, Node> nodes, List<FrameEvent> events, long version) {
        List<Node> attach = new ArrayList<>(events.size());
        List<Node> touched = new ArrayList<>(events.size());
        for (FrameEvent e : events) {
            switch (e) {
                case FrameEvent.Removed r -> {
                    Node n = nodes.remove(r.name());
                    dropReferences(nodes, r.frame());
                    detach(n);
                }
                case FrameEvent.Replaced r -> {
                    Node n = nodes.get(r.name());
                    Frame before = r.before().orElseThrow();
                    dropReferences(nodes, before);
                    if (!Objects.equals(before.parent(), r.frame().parent()) || before.kind() != r.frame().kind()) {
                        detach(n);
                        attach.add(n);
                    }
                    n.frame = r.frame();
                    n.revision = version;
                    touched.add(n);
                }
                case FrameEvent.Added a -> {
                    Node n = new Node(a.frame());
                    n.revision = version;
                    nodes.put(a.name(), n);
                    attach.add(n);
                    touched.add(n);
                }
            }
        }
        for (Node n : attach) {
            n.parent = n.frame.parent().map(nodes::get).orElse(null);
            if (n.parent != null) {
                n.parent.children().add(n);
            }
        }
        for (Node n : attach) {
            if (n.frame.isInstance()) {
                for (Node a = n.parent; a != null; a = a.parent) {
                    a.instances().add(n);
                }
            } else if (n.instances != null && !n.instances.isEmpty()) {
                for (Node a = n.parent; a != null; a = a.parent) {
                    a.instances().addAll(n.instances);
                }
            }
        }
        for (Node n : touched) {
            for (String r : References.of(n.frame)) {
                Node target = nodes.get(r);
                if (target != null) {
                    target.referrers().add(n.name());
                }
            }
        }
    }

    /** Takes a node out of its parent's children and its instances out of every ancestor's instance set. */
    private static void detach(Node n) {
        if (n.parent == null) {
            return;
        }
        n.parent.children.remove(n);
        Set<Node> below = n.frame.isInstance() ? Set.of(n) : n.instances;
        if (below != null && !below.isEmpty()) {
            for (Node a = n.parent; a != null; a = a.parent) {
                if (a.instances != null) {
                    a.instances.removeAll(below);
                }
            }
        }
        n.parent = null;
    }

    private static void dropReferences(Map<String, Node> nodes, Frame before) {
        for (String r : References.of(before)) {
            Node target = nodes.get(r);
            if (target != null && target.referrers != null) {
                target.referrers.remove(before.name());
            }
        }
    }
}
