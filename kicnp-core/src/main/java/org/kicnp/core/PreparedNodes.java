package org.kicnp.core;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The nodes of a {@link StagedBatch}, built while it is staged, on the thread that stages it: each node with its
 * parent and, among the batch's own nodes, its children, instances and referrers, exactly as {@link Indexer} would
 * leave them. The knowledge base's own nodes are not touched until {@link #attach}, under the write lock, links the
 * new nodes to them; so the commit of a large load does little more than put the nodes in the name index.
 *
 * <p>This works while each frame comes after its parent and after the frames it refers to (as a saved knowledge base
 * is written); otherwise {@link #add} answers false and the batch is indexed at the commit as any other.
 */
final class PreparedNodes {
    /** The revision of a node not yet in the knowledge base. */
    private static final long PENDING = -1;

    private final NodeIndex base;
    private final Map<String, Node> byName = new HashMap<>();
    private final List<Node> nodes = new ArrayList<>();
    /** Pairs (referrer, target) whose target is a node of the knowledge base, in the order found. */
    private final List<Node> baseReferences = new ArrayList<>();
    private final List<String> refs = new ArrayList<>();

    PreparedNodes(NodeIndex base) {
        this.base = base;
    }

    /**
     * Builds the node of the next staged frame; false (and this object is then of no more use) when its parent or a
     * frame it refers to is not known yet. Runs under the knowledge base's read lock.
     */
    boolean add(Frame f) {
        Node n = new Node(f);
        n.revision = PENDING;
        byName.put(f.name(), n);
        String p = f.parentOrNull();
        if (p != null) {
            Node parent = byName.get(p);
            if (parent == null) {
                parent = base.get(p);
                if (parent == null) {
                    return false;
                }
            }
            n.parent = parent;
            if (parent.revision == PENDING) {
                parent.children().add(n);
            }
        }
        if (f.isInstance()) {
            for (Node a = n.parent; a != null && a.revision == PENDING; a = a.parent) {
                a.instances().add(n);
            }
        }
        refs.clear();
        References.collect(f, refs);
        for (int i = 0, count = refs.size(); i < count; i++) {
            Node target = byName.get(refs.get(i));
            if (target == n) {
                continue;
            }
            if (target != null) {
                target.addReferrer(n);
            } else {
                target = base.get(refs.get(i));
                if (target == null) {
                    return false;
                }
                baseReferences.add(n);
                baseReferences.add(target);
            }
        }
        nodes.add(n);
        return true;
    }

    /** Links the new nodes to the knowledge base's and puts them in {@code index}; under the write lock. */
    void attach(NodeIndex index, long version) {
        for (Node n : nodes) {
            Node p = n.parent;
            if (p != null && p.revision != PENDING) {
                p.children().add(n);
            }
            if (n.frame.isInstance()) {
                for (Node a = p; a != null; a = a.parent) {
                    if (a.revision != PENDING) {
                        a.instances().add(n);
                    }
                }
            }
        }
        for (int i = 0; i < baseReferences.size(); i += 2) {
            baseReferences.get(i + 1).addReferrer(baseReferences.get(i));
        }
        for (Node n : nodes) {
            n.revision = version;
            index.put(n.name(), n);
            n.liveIn = index;
            n.frame.node = n;
        }
    }
}
