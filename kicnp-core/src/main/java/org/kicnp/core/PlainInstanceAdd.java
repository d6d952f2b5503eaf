package org.kicnp.core;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

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
    private final NodeIndex nodes;
    /** The knowledge base's own memo of checked classes (cleared by any batch that changes a class). */
    private final Map<String, ClassInfo> classes;
    /** The nodes of the instance slots' values of the frame being checked, by slot position; reused, for one add. */
    private Node[] targets = new Node[4];

    PlainInstanceAdd(NodeIndex nodes, Map<String, ClassInfo> classes) {
        this.nodes = nodes;
        this.classes = classes;
    }

    /**
     * Makes one change, the add of a plain instance that passes every check, and returns its event; or returns null,
     * having changed nothing, when the change is anything else.
     *
     * @param near frames the instance may refer to, at hand ({@link Node#find}); nulls allowed; or null
     */
    List<FrameEvent> tryAdd(Change change, Frame[] near, long version) {
        if (!(change instanceof Change.Add a)) {
            return null;
        }
        Frame f = a.frame();
        Node parent = check(f, near);
        if (parent == null) {
            return null;
        }
        Node n = new Node(f);
        if (!nodes.putNew(f.name(), NameTable.numberOf(f), n)) { // the name's one probe, as the last check
            return null;
        }
        link(n, parent, targets, version);
        return List.of(new FrameEvent.Added(f));
    }

    /**
     * Adds every frame of a batch of adds and returns their events, in order, or returns null, having changed
     * nothing, unless each one is a plain instance that passes every check on the knowledge base as it was before the
     * batch (so none refers to another of the batch) and no name comes twice or is taken. The names are put in the
     * name index as the last check (one probe each, where a look-up before the checks and a put after them took two,
     * and a table of the batch's names a third); a name found there (taken, or given twice) takes the batch's names
     * out again.
     */
    List<FrameEvent> tryBatch(List<? extends Change> changes, long version) {
        int n = changes.size();
        Frame[] frames = new Frame[n];
        Node[] parents = new Node[n];
        int[] numbers = new int[n];
        Node[][] targetsOf = new Node[n][];
        int hashed = 0;
        for (int i = 0; i < n; i++) {
            if (!(changes.get(i) instanceof Change.Add a)) {
                return null;
            }
            frames[i] = a.frame();
            numbers[i] = NameTable.numberOf(frames[i]);
            hashed += numbers[i] < 0 ? 1 : 0;
            parents[i] = check(frames[i], null);
            if (parents[i] == null) {
                return null;
            }
            targetsOf[i] = copyOfTargets(frames[i].slots().size());
        }
        nodes.ensureRoom(hashed, n - hashed);
        Node[] made = new Node[n];
        for (int i = 0; i < n; i++) {
            made[i] = new Node(frames[i]);
            if (!nodes.putNew(frames[i].name(), numbers[i], made[i])) {
                for (int j = 0; j < i; j++) {
                    nodes.remove(frames[j].name());
                }
                return null;
            }
        }
        FrameEvent[] events = new FrameEvent[n];
        for (int i = 0; i < n; i++) {
            link(made[i], parents[i], targetsOf[i], version);
            events[i] = new FrameEvent.Added(frames[i]);
        }
        return Arrays.asList(events);
    }

    /** The first {@code n} of {@link #targets} for keeping, or null when none of them is set. */
    private Node[] copyOfTargets(int n) {
        for (int i = 0; i < n; i++) {
            if (targets[i] != null) {
                return Arrays.copyOf(targets, n);
            }
        }
        return null;
    }

    /**
     * The checks of a plain instance against the knowledge base as it is, but for its name (the caller's put in the
     * name index, {@link NodeIndex#putNew}, is the last check): answers its class's node, with the nodes of its
     * instance slots' values in {@link #targets} (by slot position, null for other slots), when every check is
     * passed; else null.
     */
    private Node check(Frame f, Frame[] near) {
        if (!f.isInstance() || f.provenance().durable() || !f.parts().isEmpty() || !f.linksTo().isEmpty()
                || !f.linksFrom().isEmpty()) {
            return null;
        }
        ClassInfo cls = known(f.parentOrNull());
        if (cls == null) {
            return null;
        }
        List<Slot> slots = f.slots();
        int n = slots.size();
        if (targets.length < n) {
            targets = new Node[Math.max(n, 2 * targets.length)];
        }
        Declarations declared = n == 0 ? Declarations.NONE : cls.declarations();
        for (int i = 0; i < n; i++) {
            targets[i] = null;
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
                    ClassInfo argument = d == null || d.slot().type() != DataType.INSTANCE ? null
                            : known(d.argument());
                    if (argument == null || !(s.valueOrNull() instanceof Value.Ref ref)) {
                        return null;
                    }
                    Node target = Node.find(nodes, ref.frame(), near);
                    if (target == null || !isA(target, argument)) {
                        return null;
                    }
                    targets[i] = target;
                }
                default -> {
                    return null;
                }
            }
        }
        return classNode(cls);
    }

    /** The node of a checked class, or null when the knowledge base holds another frame of its name. */
    private Node classNode(ClassInfo cls) {
        Node parent = cls.frame.node;
        if (parent == null || parent.liveIn != nodes) {
            parent = nodes.get(cls.frame.name()); // a frame shared with another knowledge base points at its node there
        }
        return parent != null && parent.frame == cls.frame ? parent : null;
    }

    /**
     * Makes one change, the add of the instance of a {@linkplain InstanceShape prepared shape} named {@code name}
     * with {@code values} in its slots, when it passes every check, and returns its event; or returns null, having
     * changed nothing, when any check fails or cannot be answered at once (the caller then adds the frame the general
     * way, which reports the problems). The checks are those of {@link #tryAdd} for such a frame; the class and its
     * slot declarations are checked once per shape while no class changes ({@code epoch}), and the name is known to be
     * valid when it is the class's name, '-' and digits.
     */
    List<FrameEvent> tryShaped(InstanceShape shape, String name, Value[] values, Frame[] near, long version,
            long epoch) {
        InstanceShape.Resolution r = resolve(shape, epoch);
        int number = NameTable.numberOf(name);
        if (r == null || values.length != r.arguments().length || !shape.names(name, number)) {
            return null;
        }
        int n = values.length;
        if (targets.length < n) {
            targets = new Node[Math.max(n, 2 * targets.length)];
        }
        for (int i = 0; i < n; i++) {
            Node target = values[i] instanceof Value.Ref ref ? Node.find(nodes, ref.frame(), near) : null;
            if (target == null || !isA(target, r.arguments()[i])) {
                return null;
            }
            targets[i] = target;
        }
        Frame f = Frame.plain(name, shape.className(), shape.slotList(values));
        NameTable.keepNumber(f, number); // read off the name above
        Node node = new Node(f);
        if (!nodes.putNew(name, number, node)) {
            return null;
        }
        link(node, r.classNode(), targets, version);
        return List.of(new FrameEvent.Added(f));
    }

    /**
     * What this knowledge base finds for a shape while its classes are at {@code epoch}: kept in the shape, and
     * worked out again after any class changed. Null when the class is not a checked class or a slot is not one of
     * its instance slots (not kept: the general path reports it, and a later class change may mend it).
     */
    private InstanceShape.Resolution resolve(InstanceShape shape, long epoch) {
        InstanceShape.Resolution r = shape.resolution();
        if (r != null && r.nodes() == nodes && r.epoch() == epoch) {
            return r;
        }
        ClassInfo cls = known(shape.className());
        if (cls == null) {
            return null;
        }
        Declarations declared = cls.declarations();
        List<Slot> templates = shape.templates();
        ClassInfo[] arguments = new ClassInfo[templates.size()];
        for (int i = 0; i < arguments.length; i++) {
            Declarations.Declaration d = declared.find(templates.get(i).name());
            arguments[i] = d == null || d.slot().type() != DataType.INSTANCE ? null : known(d.argument());
            if (arguments[i] == null) {
                return null;
            }
        }
        Node parent = classNode(cls);
        if (parent == null) {
            return null;
        }
        r = new InstanceShape.Resolution(nodes, epoch, parent, arguments);
        shape.resolved(r);
        return r;
    }

    /**
     * The class named {@code name} as the validator knows it: from the memo, or else worked out from the knowledge
     * base by a validator of no change (which remembers it in the memo, as any batch's validation would); null when
     * there is no such class or its chain is not complete.
     */
    private ClassInfo known(String name) {
        if (name == null) {
            return null;
        }
        ClassInfo c = classes.get(name);
        if (c == null) {
            c = new Validator(Map.of(), nodes, classes, new ArrayList<>()).classInfo(name);
        }
        return c != null && c.frame.isClass() && c.complete ? c : null;
    }

    /**
     * Whether {@code target} is the checked class {@code ancestor} or lies below it: up the parents of the knowledge
     * base's nodes (acyclic, as every committed chain is), comparing frames by identity, so no name is read or looked
     * up. A class's memo entry holds the frame its node holds (both come from the batch that added or last changed
     * it, and any class change clears the memo); were it ever another, the answer is false and the caller takes the
     * general path, which decides.
     */
    private static boolean isA(Node target, ClassInfo ancestor) {
        for (Node n = target; n != null; n = n.parent) {
            if (n.frame == ancestor.frame) {
                return true;
            }
        }
        return false;
    }

    /**
     * As {@link Indexer} indexes an added instance, for a node the name index holds now: its class's children, every
     * ancestor, referrers.
     *
     * @param targets the nodes of its instance slots' values, nulls allowed; or null when it has none
     */
    private void link(Node n, Node parent, Node[] targets, long version) {
        Frame f = n.frame;
        n.revision = version;
        n.liveIn = nodes;
        f.node = n;
        n.parent = parent;
        parent.children().addNew(n);
        for (Node a = parent; a != null; a = a.parent) {
            a.instances().addNew(n);
        }
        if (targets != null) {
            for (int i = 0, k = Math.min(targets.length, f.slots().size()); i < k; i++) {
                if (targets[i] != null) {
                    targets[i].addReferrer(n); // a probe: two slots may hold the same instance
                }
            }
        }
    }
}
