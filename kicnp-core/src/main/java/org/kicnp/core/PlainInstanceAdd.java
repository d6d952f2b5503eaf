package org.kicnp.core;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Adds of plain instances — runtime instances of a class already checked, whose slots each hold a value of the type
 * their class declares (a number, text or truth value, or one instance of the slot's class), with no parts, links,
 * arguments, defaults or slot conditions of their own: what sensors assert and an inference engine derives — checked
 * and indexed directly, without staging a batch.
 *
 * <p>The checks are the validator's for that shape ({@link Validator}: the parent is a class with an acyclic IS-A
 * chain, each slot has the type its class declares, an instance slot's class exists and its instance lies below it),
 * made from what the knowledge base keeps between batches; the indexes are the ones {@link Indexer} builds for an
 * add. A frame of any other shape, or one any check fails or cannot answer at once (its class is not known yet, a
 * slot names a frame that is not there yet, a name is taken or given twice), is not added here, and the caller
 * commits the batch the general way, which reports the problems: so a change ends the same either way
 * ({@code PlainInstanceAddTest}). Runs under the write lock.
 */
final class PlainInstanceAdd {
    private static final Node[] NO_TARGETS = new Node[0];

    private PlainInstanceAdd() {
    }

    /**
     * Makes one change, the add of a plain instance that passes every check, and returns its event; or returns null,
     * having changed nothing, when the change is anything else.
     *
     * @param classes the knowledge base's own memo of checked classes (cleared by any batch that changes a class)
     * @param near frames the instance may refer to, at hand ({@link Node#find}); nulls allowed; or null
     */
    static List<FrameEvent> tryAdd(Change change, NodeIndex nodes, Map<String, ClassInfo> classes, Frame[] near,
            long version) {
        Checked c = change instanceof Change.Add a ? check(a.frame(), nodes, classes, near) : null;
        if (c == null) {
            return null;
        }
        index(c, nodes, version);
        return List.of(new FrameEvent.Added(c.frame));
    }

    /**
     * Adds every frame of a batch of adds and returns their events, in order, or returns null, having changed
     * nothing, unless each one is a plain instance that passes every check on the knowledge base as it was before the
     * batch (so none refers to another of the batch) and no name comes twice.
     */
    static List<FrameEvent> tryBatch(List<? extends Change> changes, NodeIndex nodes, Map<String, ClassInfo> classes,
            long version) {
        int n = changes.size();
        Checked[] checked = new Checked[n];
        Set<String> names = HashSet.newHashSet(n);
        for (int i = 0; i < n; i++) {
            if (!(changes.get(i) instanceof Change.Add a) || !names.add(a.frame().name())) {
                return null;
            }
            checked[i] = check(a.frame(), nodes, classes, null);
            if (checked[i] == null) {
                return null;
            }
        }
        List<FrameEvent> events = new ArrayList<>(n);
        for (Checked c : checked) {
            index(c, nodes, version);
            events.add(new FrameEvent.Added(c.frame));
        }
        return events;
    }

    /** A plain instance that passed: its class's node and the nodes its slots' instances have. */
    private record Checked(Frame frame, Node parent, Node[] targets) {
    }

    /** The checks of a plain instance against the knowledge base as it is; null when any is not passed. */
    private static Checked check(Frame f, NodeIndex nodes, Map<String, ClassInfo> classes, Frame[] near) {
        if (!f.isInstance() || f.provenance().durable() || !f.parts().isEmpty() || !f.linksTo().isEmpty()
                || !f.linksFrom().isEmpty()) {
            return null;
        }
        ClassInfo cls = known(nodes, classes, f.parentOrNull());
        if (cls == null || nodes.get(f.name()) != null) {
            return null;
        }
        List<Slot> slots = f.slots();
        int n = slots.size();
        Node[] targets = NO_TARGETS;
        Declarations declared = n == 0 ? Declarations.NONE : cls.declarations();
        for (int i = 0; i < n; i++) {
            Slot s = slots.get(i);
            if (s.valueOrNull() == null || s.argumentOrNull() != null || s.defaultOrNull() != null
                    || s.frameRelatedOrNull() != null || !s.frameListRelated().isEmpty()
                    || !(s.condition() instanceof Condition.Any)) {
                return null;
            }
            Declarations.Declaration d = declared.find(s.name());
            switch (s.type()) {
                case STRING, INTEGER, FLOAT, BOOLEAN -> {
                    if (d != null && d.slot().type() != s.type()) {
                        return null;
                    }
                }
                case INSTANCE -> {
                    String argument = d == null ? null : d.argument();
                    if (d == null || d.slot().type() != DataType.INSTANCE || argument == null
                            || known(nodes, classes, argument) == null
                            || !(s.valueOrNull() instanceof Value.Ref ref)) {
                        return null;
                    }
                    Node target = Node.find(nodes, ref.frame(), near);
                    if (target == null || !isA(nodes, classes, target.frame, argument)) {
                        return null;
                    }
                    if (targets == NO_TARGETS) {
                        targets = new Node[n];
                    }
                    targets[i] = target;
                }
                default -> {
                    return null;
                }
            }
        }
        Node parent = cls.frame.node;
        if (parent == null || parent.liveIn != nodes) {
            parent = nodes.get(cls.frame.name()); // a frame shared with another knowledge base points at its node there
        }
        if (parent == null || parent.frame != cls.frame) {
            return null;
        }
        return new Checked(f, parent, targets);
    }

    /**
     * The class named {@code name} as the validator knows it: from the memo, or else worked out from the knowledge
     * base by a validator of no change (which remembers it in the memo, as any batch's validation would); null when
     * there is no such class or its chain is not complete.
     */
    private static ClassInfo known(NodeIndex nodes, Map<String, ClassInfo> classes, String name) {
        if (name == null) {
            return null;
        }
        ClassInfo c = classes.get(name);
        if (c == null) {
            c = new Validator(Map.of(), nodes, classes, new ArrayList<>()).classInfo(name);
        }
        return c != null && c.frame.isClass() && c.complete ? c : null;
    }

    /** Whether {@code target} is {@code ancestor} or lies below it, answered from a checked class; else false. */
    private static boolean isA(NodeIndex nodes, Map<String, ClassInfo> classes, Frame target, String ancestor) {
        if (target.name().equals(ancestor)) {
            return true;
        }
        ClassInfo p = known(nodes, classes, target.parentOrNull());
        return p != null && p.isA(ancestor);
    }

    /** As {@link Indexer} indexes an added instance: its node, its class's children, every ancestor, referrers. */
    private static void index(Checked c, NodeIndex nodes, long version) {
        Frame f = c.frame;
        Node n = new Node(f);
        n.revision = version;
        nodes.put(f.name(), n);
        n.liveIn = nodes;
        f.node = n;
        n.parent = c.parent;
        c.parent.children().addNew(n);
        for (Node a = c.parent; a != null; a = a.parent) {
            a.instances().addNew(n);
        }
        for (Node t : c.targets) {
            if (t != null) {
                t.referrers().add(n); // a probe: two slots may hold the same instance
            }
        }
    }
}
