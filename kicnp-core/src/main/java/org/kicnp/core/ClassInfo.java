package org.kicnp.core;

import java.util.ArrayList;
import java.util.List;

/**
 * A frame whose IS-A chain is known to end at a root without a cycle, linked to its parent's entry, and (computed
 * when first asked) the slot declarations it inherits and makes. The validator keeps these per batch, so a large load
 * walks each chain once; between batches that change no class the knowledge base keeps them, so adding an instance
 * costs one look-up instead of a walk up the hierarchy and a map per ancestor.
 */
final class ClassInfo {
    final Frame frame;
    /** The parent's entry, or null for a root or a frame whose parent is not defined. */
    final ClassInfo parent;
    /** Whether the chain ends at a root, not at a parent that is not defined (yet: a staged load may add it later). */
    final boolean complete;
    private Declarations declarations;

    ClassInfo(Frame frame, ClassInfo parent) {
        this.frame = frame;
        this.parent = parent;
        this.complete = parent == null ? frame.parentOrNull() == null : parent.complete;
    }

    /** Whether this frame is named {@code ancestor} or lies below it. */
    boolean isA(String ancestor) {
        for (ClassInfo c = this; c != null; c = c.parent) {
            if (c.frame.name().equals(ancestor)) {
                return true;
            }
        }
        return false;
    }

    /** The declarations of this frame and everything above it; built top-down without recursion. */
    Declarations declarations() {
        if (declarations != null) {
            return declarations;
        }
        List<ClassInfo> missing = new ArrayList<>(8);
        ClassInfo c = this;
        while (c != null && c.declarations == null) {
            missing.add(c);
            c = c.parent;
        }
        Declarations above = c == null ? Declarations.NONE : c.declarations;
        for (int i = missing.size() - 1; i >= 0; i--) {
            ClassInfo x = missing.get(i);
            x.declarations = above.plus(x.frame);
            above = x.declarations;
        }
        return above;
    }
}
