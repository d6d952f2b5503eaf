package org.kicnp.core;

import java.util.List;
import java.util.Map;

/**
 * The add of one plain instance — a runtime instance of a class already checked, whose slots each hold one instance
 * in an instance slot its class declares, with no parts, links, arguments, defaults or slot conditions of its own: what an
 * inference engine derives at every firing — checked and indexed directly, without staging a batch of one change.
 *
 * <p>The checks are the validator's for that shape ({@link Validator}: the parent is a class with an acyclic IS-A
 * chain, each slot has the type its class declares and an argument class that exists, each slot's instance exists and
 * lies below that class), made from what the knowledge base keeps between batches; the indexes are the ones
 * {@link Indexer} builds for an add. A frame of any other shape, or one any check fails or cannot answer at once
 * (its class is not known yet, a slot names a frame that is not there), is not added here, and the caller commits it
 * as a batch, which reports the problems: so an add gives the same outcome either way ({@code PlainInstanceAddTest}).
 * Runs under the write lock.
 */
final class PlainInstanceAdd {
    private PlainInstanceAdd() {
    }

    /**
     * Adds {@code f} and returns its event, or returns null, having changed nothing, when {@code f} is not a plain
     * instance that passes every check.
     *
     * @param classes the knowledge base's own memo of checked classes (cleared by any batch that changes a class)
     * @param near frames {@code f} may refer to, at hand ({@link Node#find}); nulls allowed
     */
    static FrameEvent.Added tryAdd(Frame f, NodeIndex nodes, Map<String, ClassInfo> classes, Frame[] near,
            long version) {
        if (!f.isInstance() || f.provenance().durable() || !f.parts().isEmpty() || !f.linksTo().isEmpty()
                || !f.linksFrom().isEmpty()) {
            return null;
        }
        ClassInfo cls = known(classes, f.parentOrNull());
        if (cls == null || !cls.complete || nodes.get(f.name()) != null) {
            return null;
        }
        List<Slot> slots = f.slots();
        int n = slots.size();
        Node[] targets = new Node[n];
        Declarations declared = n == 0 ? Declarations.NONE : cls.declarations();
        for (int i = 0; i < n; i++) {
            Slot s = slots.get(i);
            if (s.type() != DataType.INSTANCE || !(s.valueOrNull() instanceof Value.Ref ref)
                    || s.argumentOrNull() != null || s.defaultOrNull() != null || s.frameRelatedOrNull() != null || !s.frameListRelated().isEmpty()
                    || !(s.condition() instanceof Condition.Any)) {
                return null;
            }
            Declarations.Declaration d = declared.find(s.name());
            String argument = d == null ? null : d.argument();
            if (d == null || d.slot().type() != DataType.INSTANCE || argument == null
                    || known(classes, argument) == null) {
                return null;
            }
            Node target = Node.find(nodes, ref.frame(), near);
            if (target == null || !isA(classes, target.frame, argument)) {
                return null;
            }
            targets[i] = target;
        }
        Node parent = cls.frame.node;
        if (parent == null || parent.liveIn != nodes) {
            parent = nodes.get(cls.frame.name()); // a frame shared with another knowledge base points at its node there
        }
        if (parent == null || parent.frame != cls.frame) {
            return null;
        }
        index(f, nodes, parent, targets, version);
        return new FrameEvent.Added(f);
    }

    /** The checked class named {@code name}, or null when none is known (the validator would look it up). */
    private static ClassInfo known(Map<String, ClassInfo> classes, String name) {
        ClassInfo c = name == null ? null : classes.get(name);
        return c != null && c.frame.isClass() ? c : null;
    }

    /** Whether {@code target} is {@code ancestor} or lies below it, answered from a checked class; else false. */
    private static boolean isA(Map<String, ClassInfo> classes, Frame target, String ancestor) {
        if (target.name().equals(ancestor)) {
            return true;
        }
        ClassInfo p = known(classes, target.parentOrNull());
        return p != null && p.isA(ancestor);
    }

    /** As {@link Indexer} indexes an added instance: its node, its class's children, every ancestor, referrers. */
    private static void index(Frame f, NodeIndex nodes, Node parent, Node[] targets, long version) {
        Node n = new Node(f);
        n.revision = version;
        nodes.put(f.name(), n);
        n.liveIn = nodes;
        f.node = n;
        n.parent = parent;
        parent.children().addNew(n);
        for (Node a = parent; a != null; a = a.parent) {
            a.instances().addNew(n);
        }
        for (Node t : targets) {
            t.referrers().add(n); // a probe: two slots may hold the same instance
        }
    }
}
