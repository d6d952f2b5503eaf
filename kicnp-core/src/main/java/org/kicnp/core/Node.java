package org.kicnp.core;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The knowledge base's bookkeeping for one frame: the frame itself, its revision, and the derived indexes
 * (children, every instance below a class, the frames that refer to it). Mutated only under the write lock. A
 * replace keeps the node, so the name never changes.
 */
final class Node {
    Frame frame;
    long revision;
    Node parent;
    /** Direct children: subclasses and instances whose A-kind-of is this frame. Derived; never stored. */
    NodeSet children;
    /** For a class: every instance of it or of any descendant class, in insertion order. */
    NodeSet instances;
    /**
     * Frames whose slots, parts or links mention this frame (A-kind-of is tracked by children), in the order they came
     * to, each once: null (none), the one referrer itself, a {@code Node[]} of at most {@value #FEW_REFERRERS} padded
     * with trailing nulls, or, past that, a {@link NodeSet}. Most referred frames have one to three referrers all their
     * life (an instance a few derived instances name), and a set of its own (an object and an array, 56 to 64 bytes)
     * for each was about a twentieth of what a run of {@code bench inference} keeps.
     */
    private Object referrers;
    /** Its place in the name index's order ({@link NodeIndex}); -1 when not in an index. */
    int order = -1;
    /** The name index that holds this node now, or null before it is put there and once it is removed. */
    NodeIndex liveIn;

    Node(Frame frame) {
        this.frame = frame;
    }

    String name() {
        return frame.name();
    }

    NodeSet children() {
        if (children == null) {
            children = new NodeSet(4);
        }
        return children;
    }

    NodeSet instances() {
        if (instances == null) {
            instances = new NodeSet(4);
        }
        return instances;
    }

    /** At most this many referrers are kept in a plain array, searched linearly; one more makes a {@link NodeSet}. */
    static final int FEW_REFERRERS = 8;

    /** Adds {@code r} to the referrers at the end unless it is one already. */
    void addReferrer(Node r) {
        Object rs = referrers;
        if (rs == null) {
            referrers = r;
        } else if (rs instanceof Node one) {
            if (one != r) {
                referrers = new Node[] {one, r};
            }
        } else if (rs instanceof Node[] few) {
            int n = 0;
            while (n < few.length && few[n] != null) {
                if (few[n] == r) {
                    return;
                }
                n++;
            }
            if (n < few.length) {
                few[n] = r;
            } else if (n < FEW_REFERRERS) {
                Node[] grown = Arrays.copyOf(few, Math.min(FEW_REFERRERS, 2 * n));
                grown[n] = r;
                referrers = grown;
            } else {
                NodeSet set = new NodeSet(2 * n);
                for (Node x : few) {
                    set.addNew(x);
                }
                set.addNew(r);
                referrers = set;
            }
        } else {
            ((NodeSet) rs).add(r);
        }
    }

    /** Removes {@code r} from the referrers, keeping the others' order. */
    void removeReferrer(Node r) {
        Object rs = referrers;
        if (rs == r) {
            referrers = null;
        } else if (rs instanceof Node[] few) {
            int n = 0;
            while (n < few.length && few[n] != null) {
                n++;
            }
            for (int i = 0; i < n; i++) {
                if (few[i] == r) {
                    System.arraycopy(few, i + 1, few, i, n - i - 1);
                    few[n - 1] = null;
                    referrers = n == 2 ? few[0] : few;
                    return;
                }
            }
        } else if (rs instanceof NodeSet set) {
            set.remove(r);
            if (set.isEmpty()) {
                referrers = null;
            }
        }
    }

    /** The referrers, in the order they came to refer to this frame (a copy). */
    List<Node> referrers() {
        Object rs = referrers;
        if (rs == null) {
            return List.of();
        }
        if (rs instanceof Node one) {
            return List.of(one);
        }
        List<Node> out = new ArrayList<>();
        if (rs instanceof Node[] few) {
            for (Node x : few) {
                if (x == null) {
                    break;
                }
                out.add(x);
            }
        } else {
            for (Node x : (NodeSet) rs) {
                out.add(x);
            }
        }
        return out;
    }

    boolean hasChildren() {
        return children != null && !children.isEmpty();
    }

    /**
     * The node of {@code name} in {@code index}: reached through a frame of {@code near} (frames a caller had at hand,
     * nulls allowed) whose node {@code index} holds now, without looking the name up, or else looked up. Either way
     * it is {@code index.get(name)}: a frame's node is the one it was last made the frame of, and a node is in
     * {@code index} exactly while its {@link #liveIn} is {@code index}.
     */
    static Node find(NodeIndex index, String name, Frame[] near) {
        if (near != null) {
            for (Frame f : near) {
                if (f != null) {
                    String at = f.name();
                    Node n = f.node;
                    // equals, not hashes first: the names are short, most differ in length or first letters, and
                    // a name the engine made a moment ago has no hash yet
                    if (n != null && n.liveIn == index && (at == name || at.equals(name))) {
                        return n;
                    }
                }
            }
        }
        return index.get(name);
    }
}
