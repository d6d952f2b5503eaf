package org.kicnp.core;

/**
 * The knowledge base's bookkeeping for one frame: the frame itself, its revision, and the derived indexes
 * (children, every instance below a class, the frames that refer to it). Mutated only under the write lock. A
 * replace keeps the node, so the name (and its hash) never changes.
 */
final class Node {
    final int hash;
    Frame frame;
    long revision;
    Node parent;
    /** Direct children: subclasses and instances whose A-kind-of is this frame. Derived; never stored. */
    NodeSet children;
    /** For a class: every instance of it or of any descendant class, in insertion order. */
    NodeSet instances;
    /** Frames whose slots, parts or links mention this frame (A-kind-of is tracked by children). */
    NodeSet referrers;

    Node(Frame frame) {
        this.frame = frame;
        this.hash = frame.name().hashCode();
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
}
