package org.kicnp.core;

import java.util.LinkedHashSet;
import java.util.Set;

/**
 * The knowledge base's bookkeeping for one frame: the frame itself, its revision, and the derived indexes
 * (children, every instance below a class, the frames that refer to it). Mutated only under the write lock.
 */
final class Node {
    Frame frame;
    long revision;
    Node parent;
    /** Direct children: subclasses and instances whose A-kind-of is this frame. Derived; never stored. */
    Set<Node> children;
    /** For a class: every instance of it or of any descendant class, in insertion order. */
    Set<Node> instances;
    /** Names of frames whose slots, parts or links mention this frame (A-kind-of is tracked by children). */
    Set<String> referrers;

    Node(Frame frame) {
        this.frame = frame;
    }

    String name() {
        return frame.name();
    }

    Set<Node> children() {
        if (children == null) {
            children = new LinkedHashSet<>(4);
        }
        return children;
    }

    Set<Node> instances() {
        if (instances == null) {
            instances = new LinkedHashSet<>(4);
        }
        return instances;
    }

    Set<String> referrers() {
        if (referrers == null) {
            referrers = new LinkedHashSet<>(2);
        }
        return referrers;
    }

    boolean hasChildren() {
        return children != null && !children.isEmpty();
    }
}
