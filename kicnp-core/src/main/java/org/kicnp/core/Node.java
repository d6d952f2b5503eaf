package org.kicnp.core;

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
    /** Frames whose slots, parts or links mention this frame (A-kind-of is tracked by children). */
    NodeSet referrers;
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

    NodeSet referrers() {
        if (referrers == null) {
            referrers = new NodeSet(2);
        }
        return referrers;
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
