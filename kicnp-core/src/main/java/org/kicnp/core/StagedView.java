package org.kicnp.core;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The knowledge base as it would be after a staged batch, for the {@link Validator}: each name's frame (the batch's
 * own where it touches the name, else the knowledge base's), and what is known of the IS-A chains of its classes.
 *
 * <p>Kept apart from the checks because it is the one part with a memory: chains are worked out once and remembered as
 * {@link ClassInfo}s (in the map the validator was given, which may be the knowledge base's own) and chains found to
 * run into a cycle are remembered too, so a load of many frames walks each chain once. The checks only ask questions
 * of it and collect problems.
 */
final class StagedView {
    private static final int CYCLE_CHECK_STEPS = 10_000;
    /** How many frames of an IS-A cycle a problem names: a cycle may run through thousands. */
    private static final int CYCLE_TEXT_NAMES = 10;

    private final Map<String, Frame> staged;
    private final NodeIndex base;
    /** Frames known to have an acyclic IS-A chain in the view, by name. */
    private final Map<String, ClassInfo> classes;
    /** Frames found to have an IS-A cycle in their chain, so no other frame walks it again; null until one is. */
    private Set<String> cyclic;
    /** Frames the batch's frames refer to, at hand ({@link Node#find}); null: none. */
    private final Frame[] near;

    /** As the {@link Validator}'s constructor takes them. */
    StagedView(Map<String, Frame> staged, NodeIndex base, Map<String, ClassInfo> classes, Frame[] near) {
        this.staged = staged;
        this.base = base;
        this.classes = classes;
        this.near = near;
    }

    /** The frame of that name after the batch, or null where there is none. */
    Frame get(String name) {
        Frame f = staged.get(name);
        if (f != null || staged.containsKey(name)) {
            return f;
        }
        Node n = base.get(name);
        return n == null ? null : n.frame;
    }

    /** As {@link #get}, for a name a frame refers to: reached through the frames at hand where one has it. */
    Frame referred(String name) {
        Frame f = staged.get(name);
        if (f != null || staged.containsKey(name)) {
            return f;
        }
        Node n = Node.find(base, name, near);
        return n == null ? null : n.frame;
    }

    /** Whether frame {@code f} is {@code ancestor} or lies below it in the view. */
    boolean isA(Frame f, String ancestor) {
        if (f.name().equals(ancestor)) {
            return true;
        }
        String p = f.parentOrNull();
        ClassInfo known = p == null ? null : knownClass(p);
        if (known != null) {
            return known.isA(ancestor); // the common case: an instance of a class checked before
        }
        Frame parent = p == null ? null : get(p);
        if (parent == null) {
            return false;
        }
        if (parent.isClass()) {
            ClassInfo c = info(parent);
            if (c != null) {
                return c.isA(ancestor);
            }
        }
        // A parent that is an instance or a chain with a cycle: reported elsewhere; walk, bounded.
        int steps = 0;
        for (Frame x = parent; x != null && steps++ < 100_000; x = parentOf(x)) {
            if (x.name().equals(ancestor)) {
                return true;
            }
        }
        return false;
    }

    /**
     * What is known of the class named {@code name} in the view, worked out (and remembered, as any check does) when
     * it is not known yet; null when the view has no class of that name or its IS-A chain has a cycle.
     */
    ClassInfo classInfo(String name) {
        Frame f = get(name);
        return f == null || !f.isClass() ? null : info(f);
    }

    /**
     * What is known already of the class named {@code name} in the view, without looking it up there: an entry of
     * {@link #classes} is made only for a class of the view whose IS-A chain ends at a root, and stays true while the
     * map is in use (the knowledge base's own map is cleared by a batch that changes a class). Null when nothing is
     * known yet; then the caller reads the view.
     */
    ClassInfo knownClass(String name) {
        ClassInfo c = classes.get(name);
        return c != null && c.frame.isClass() ? c : null;
    }

    /**
     * What is known of frame {@code x}'s IS-A chain, or null when the chain has a cycle. Walks up only to the first
     * frame already known, so a load walks each chain once, and remembers every frame on the way.
     */
    ClassInfo info(Frame x) {
        ClassInfo known = classes.get(x.name());
        if (known != null) {
            return known;
        }
        String p = x.parentOrNull();
        ClassInfo up = p == null ? null : classes.get(p);
        if (p == null || up != null) {
            // The common case in a load: parents come before their children.
            ClassInfo c = new ClassInfo(x, up);
            classes.put(x.name(), c);
            return c;
        }
        if (cyclic != null && cyclic.contains(x.name())) {
            return null;
        }
        List<Frame> path = new ArrayList<>(8);
        int nextCheck = CYCLE_CHECK_STEPS;
        ClassInfo top = null;
        for (Frame y = x; y != null; ) {
            path.add(y);
            if (path.size() > nextCheck) {
                if (repeats(path)) {
                    return cyclic(path);
                }
                nextCheck *= 2;
            }
            String yp = y.parentOrNull();
            if (yp == null) {
                break;
            }
            if (cyclic != null && cyclic.contains(yp)) {
                return cyclic(path);
            }
            top = classes.get(yp);
            if (top != null) {
                break;
            }
            y = get(yp);
        }
        for (int i = path.size() - 1; i >= 0; i--) {
            top = new ClassInfo(path.get(i), top);
            // A chain that ends at a parent not defined may be completed by a later part of a staged load.
            if (top.complete) {
                classes.put(path.get(i).name(), top);
            }
        }
        return top;
    }

    /** Remembers that every frame of {@code path} leads into an IS-A cycle (a chain never changes in a view). */
    private ClassInfo cyclic(List<Frame> path) {
        if (cyclic == null) {
            cyclic = new HashSet<>();
        }
        for (Frame f : path) {
            cyclic.add(f.name());
        }
        return null;
    }

    private static boolean repeats(List<Frame> path) {
        Set<String> seen = new HashSet<>();
        for (Frame f : path) {
            if (!seen.add(f.name())) {
                return true;
            }
        }
        return false;
    }

    private Frame parentOf(Frame f) {
        String p = f.parentOrNull();
        return p == null ? null : get(p);
    }

    /** The IS-A chain from {@code f} up to where it repeats, for a problem: the first frames of a long one. */
    String cycleText(Frame f) {
        List<String> path = new ArrayList<>();
        Set<String> seen = new HashSet<>();
        Frame x = f;
        while (x != null && seen.add(x.name())) {
            if (path.size() == CYCLE_TEXT_NAMES) {
                return String.join(" -> ", path) + " -> and further frames";
            }
            path.add(x.name());
            x = parentOf(x);
        }
        if (x != null) {
            path.add(x.name());
        }
        return String.join(" -> ", path);
    }
}
