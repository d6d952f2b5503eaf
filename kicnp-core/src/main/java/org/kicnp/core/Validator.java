package org.kicnp.core;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Checks a staged batch against the knowledge base as it would be after the batch ({@code view}), collecting every
 * problem rather than stopping at the first. Reads only; the knowledge base applies the batch if nothing is found.
 *
 * <p>Runs for every change, from a load of a hundred thousand frames to one instance per rule firing, so the common
 * path allocates little: IS-A chains and inherited slot declarations come from {@link ClassInfo}s (per batch, or the
 * knowledge base's own between batches that change no class), and messages are only built for problems found.
 */
final class Validator {
    private final Map<String, Frame> staged;
    private final NodeIndex base;
    /** The knowledge base after the batch, with what is known of its IS-A chains. */
    private final StagedView view;
    private final List<Problem> problems = new ArrayList<>(0);
    /** Staged frames by parent name, for parents that are missing or instances in the view; null until one is. */
    private Map<String, List<String>> stagedChildren;
    /** In a load staged in parts: frames whose parent was, when staged, missing or an instance. */
    private List<Frame> suspects;
    /** Scratch list for the names a frame mentions, the knowledge base's (used under its write lock). */
    private final List<String> refs;

    /**
     * @param staged touched names to their frame after the batch, or null where the batch removes the frame
     * @param base the knowledge base's nodes before the batch
     * @param classes what is known of the view's classes: the knowledge base's own when the batch changes no class
     *     (entries added here stay true), else an empty map for this batch
     * @param refs an empty list to reuse
     */
    Validator(Map<String, Frame> staged, NodeIndex base, Map<String, ClassInfo> classes, List<String> refs) {
        this(staged, base, classes, refs, null);
    }

    /**
     * As {@link #Validator(Map, NodeIndex, Map, List)}, with frames the batch's frames may refer to at hand: their
     * nodes are reached without looking their names up ({@link Node#find}; the view is the same).
     */
    Validator(Map<String, Frame> staged, NodeIndex base, Map<String, ClassInfo> classes, List<String> refs,
            Frame[] near) {
        this.staged = staged;
        this.base = base;
        this.view = new StagedView(staged, base, classes, near);
        this.refs = refs;
    }

    List<Problem> validate() {
        Frame[] parents = new Frame[staged.size()];
        int i = 0;
        for (Map.Entry<String, Frame> e : staged.entrySet()) {
            Frame f = e.getValue();
            String p = f == null ? null : f.parentOrNull();
            if (p != null) {
                Frame parent = view.get(p);
                parents[i] = parent;
                if (parent == null || parent.isInstance()) {
                    childOf(p, e.getKey());
                }
            }
            i++;
        }
        i = 0;
        for (Map.Entry<String, Frame> e : staged.entrySet()) {
            if (e.getValue() == null) {
                checkRemoval(e.getKey());
            } else {
                checkFrame(e.getValue(), parents[i]);
            }
            i++;
        }
        return problems;
    }

    private void checkRemoval(String name) {
        Node node = base.get(name);
        List<String> kids = childrenInView(name, node);
        if (!kids.isEmpty()) {
            boolean instances = kids.stream().map(view::get).allMatch(Frame::isInstance);
            problems.add(Problem.of(name, "Frame '" + name + "' cannot be removed: it still has "
                    + (instances ? "instances " : "subclasses or instances ") + quoteList(kids) + "."));
        }
        if (node != null) {
            for (Node r : node.referrers()) {
                if (!staged.containsKey(r.name())) {
                    problems.add(Problem.of(name, "Frame '" + name + "' cannot be removed: frame '" + r.name()
                            + "' refers to it."));
                }
            }
        }
    }

    /**
     * Checks one frame of a load staged in parts (adds only, on an unchanged knowledge base) against the frames staged
     * so far. True when the frame is settled: it has no problem now and its IS-A chain ends at a root, and then no
     * later add can give it one, except sub-frames of an instance, which {@link #finish} looks for. Other frames are
     * checked again by {@link #finish}, once every frame is staged.
     */
    boolean settles(Frame f) {
        int before = problems.size();
        String p = f.parentOrNull();
        Frame parent = p == null ? null : view.get(p);
        if (p != null && (parent == null || parent.isInstance())) {
            if (suspects == null) {
                suspects = new ArrayList<>();
            }
            suspects.add(f);
        }
        boolean complete = checkFrame(f, parent);
        boolean clean = problems.size() == before;
        problems.subList(before, problems.size()).clear();
        return clean && complete;
    }

    /**
     * The problems of a load staged in parts, as {@link #validate} would find them for the whole batch: the frames
     * that did not settle are checked again in staged order, with every instance that has gained sub-frames.
     */
    List<Problem> finish(List<Frame> unsettled) {
        if (suspects != null) {
            for (Frame c : suspects) {
                Frame parent = view.get(c.parentOrNull());
                if (parent == null || parent.isInstance()) {
                    childOf(c.parentOrNull(), c.name());
                }
            }
        }
        Set<String> recheck = new HashSet<>();
        for (Frame f : unsettled) {
            recheck.add(f.name());
        }
        if (stagedChildren != null) {
            for (String p : stagedChildren.keySet()) {
                Frame f = staged.get(p);
                if (f != null && f.isInstance()) {
                    recheck.add(p);
                }
            }
        }
        if (!recheck.isEmpty()) {
            for (Map.Entry<String, Frame> e : staged.entrySet()) {
                if (recheck.contains(e.getKey())) {
                    Frame f = e.getValue();
                    checkFrame(f, f.parentOrNull() == null ? null : view.get(f.parentOrNull()));
                }
            }
        }
        return problems;
    }

    private void childOf(String parent, String child) {
        if (stagedChildren == null) {
            stagedChildren = new HashMap<>();
        }
        stagedChildren.computeIfAbsent(parent, k -> new ArrayList<>()).add(child);
    }

    /**
     * @param parent the frame's parent in the view, or null for a root frame or an undefined parent
     * @return whether the frame's IS-A chain ends at a root (not at a parent that is not defined)
     */
    private boolean checkFrame(Frame f, Frame parent) {
        String name = f.name();
        String p = f.parentOrNull();
        ClassInfo above = null;
        if (p != null) {
            if (parent == null) {
                problems.add(Problem.of(name, "Frame '" + name + "' is a kind of '" + p + "', which is not defined."));
                return false;
            }
            if (parent.isInstance()) {
                problems.add(Problem.of(name, "Frame '" + name + "' is a kind of '" + p
                        + "', which is an instance; only classes can have sub-frames."));
                return false;
            }
            // The frame's chain is the parent's plus the frame itself: it has a cycle exactly when the parent's has.
            above = view.info(parent);
            if (above == null) {
                problems.add(Problem.of(name, "Frame '" + name + "' is a kind of '" + p
                        + "', which makes an IS-A cycle: " + view.cycleText(f) + "."));
                return false;
            }
        }
        if (f.isInstance()) {
            List<String> kids = childrenInView(name, base.get(name));
            if (!kids.isEmpty()) {
                problems.add(Problem.of(name, "Frame '" + name + "' cannot be an instance: it has sub-frames "
                        + quoteList(kids) + "."));
            }
        }
        for (String part : f.parts()) {
            requireFrame(name, part, "has part");
        }
        for (SemanticLink l : f.linksTo()) {
            requireFrame(name, l.frame(), "has a " + l.relation().name().toLowerCase() + " link to");
        }
        for (SemanticLink l : f.linksFrom()) {
            requireFrame(name, l.frame(), "has a " + l.relation().name().toLowerCase() + " link from");
        }
        List<Slot> slots = f.slots();
        if (!slots.isEmpty()) {
            Declarations inherited = above == null ? Declarations.NONE : above.declarations();
            for (int i = 0, n = slots.size(); i < n; i++) {
                checkSlot(f, slots.get(i), inherited);
            }
        }
        if (f.provenance().durable()) {
            checkNoRuntimeReferences(f, parent);
        }
        return above == null || above.complete;
    }

    /** A durable frame must reload on its own after a restart, when runtime frames are gone. */
    private void checkNoRuntimeReferences(Frame f, Frame parent) {
        if (parent != null && parent.provenance() == Provenance.RUNTIME) {
            problems.add(Problem.of(f.name(), "Frame '" + f.name() + "' is kept on disk but is a kind of '"
                    + parent.name() + "', which exists only at run time."));
        }
        refs.clear();
        References.collect(f, refs);
        for (int i = 0; i < refs.size(); i++) {
            String r = refs.get(i);
            if (r.equals(f.name()) || refs.subList(0, i).contains(r)) {
                continue;
            }
            Frame target = view.referred(r);
            if (target != null && target.provenance() == Provenance.RUNTIME) {
                problems.add(Problem.of(f.name(), "Frame '" + f.name() + "' is kept on disk but refers to '" + r
                        + "', which exists only at run time; copy the values it needs instead."));
            }
        }
    }

    private void checkSlot(Frame f, Slot own, Declarations inheritedSlots) {
        String name = f.name();
        String slot = own.name();
        Declarations.Declaration inherited = inheritedSlots.find(slot);
        if (inherited != null && inherited.slot().type() != own.type()) {
            problems.add(Problem.of(name, slot, where(slot, name) + " is " + own.type().xmlName() + " but '"
                    + inherited.declaredBy().name() + "' declares it " + inherited.slot().type().xmlName() + "."));
            return;
        }
        String argument = own.argumentOrNull() != null ? own.argumentOrNull()
                : inherited == null ? null : inherited.argument();
        String instanceOf = null;
        switch (own.type()) {
            case INSTANCE -> {
                if (argument == null) {
                    problems.add(Problem.of(name, slot, where(slot, name)
                            + " holds an instance but has no ARGUMENT naming the class it must hold."));
                    return;
                }
                requireClass(name, slot, argument);
                instanceOf = argument;
            }
            case FRAME -> {
                if (argument != null) {
                    requireClass(name, slot, argument);
                }
            }
            case LIST -> {
                if (argument != null && References.isClassArgument(argument)) {
                    requireClass(name, slot, argument);
                    instanceOf = argument;
                }
                checkItems(name, slot, own.valueOrNull(), argument);
                checkItems(name, slot, own.defaultOrNull(), argument);
            }
            default -> { }
        }
        if (own.valueOrNull() != null) {
            checkRefs(name, slot, own.valueOrNull(), instanceOf);
        }
        if (own.defaultOrNull() != null) {
            checkRefs(name, slot, own.defaultOrNull(), instanceOf);
        }
        if (own.frameRelatedOrNull() != null) {
            requireFrame(name, own.frameRelatedOrNull(), "names as frame-related in slot '" + slot + "'");
        }
        for (String r : own.frameListRelated()) {
            requireFrame(name, r, "names as frame-list-related in slot '" + slot + "'");
        }
        if (!(own.condition() instanceof Condition.Any)) {
            checkPaths(f, own);
            problems.addAll(ConditionTypes.problems(view::get, f, own));
        }
    }

    private void checkPaths(Frame f, Slot own) {
        for (Operand o : own.condition().operands()) {
            if (o instanceof Operand.Path p && Inheritance.slot(view::get, f, p.head()).isEmpty()) {
                problems.add(Problem.of(f.name(), own.name(), where(own.name(), f.name()) + " has a condition on '"
                        + p.text() + "', but frame '" + f.name() + "' has no slot '" + p.head() + "'."));
            }
        }
    }

    /**
     * The items of a list must be of the type its ARGUMENT names, as the XML reader will read them back: otherwise a
     * saved or journalled list (a TYPE_INT list holding "abc") is a file the loader refuses. An integer may stand in
     * a TYPE_FLOAT list, as in a TYPE_FLOAT slot; a list of TYPE_STR, or without an ARGUMENT, takes any item.
     */
    private void checkItems(String frame, String slot, Value v, String argument) {
        if (!(v instanceof Value.Lst list) || argument == null) {
            return;
        }
        DataType itemType = DataType.parse(argument).orElse(DataType.INSTANCE);
        for (Value item : list.items()) {
            boolean fits = switch (itemType) {
                case INSTANCE, FRAME -> item instanceof Value.Ref;
                case INTEGER -> item instanceof Value.Int;
                case FLOAT -> item instanceof Value.Real || item instanceof Value.Int;
                case BOOLEAN -> item instanceof Value.Bool;
                case STRING, LIST -> true;
            };
            if (!fits) {
                problems.add(Problem.of(frame, slot, where(slot, frame) + " holds the list item '" + item.text()
                        + "', a " + item.type().xmlName() + ", but its ARGUMENT makes it a list of "
                        + (References.isClassArgument(argument) ? "instances of '" + argument + "'"
                                : itemType.xmlName()) + "."));
                return;
            }
        }
    }

    /** @param instanceOf the class a referred frame must be an instance of, or null */
    private void checkRefs(String frame, String slot, Value v, String instanceOf) {
        switch (v) {
            case Value.Ref r -> {
                Frame target = view.referred(r.frame());
                if (target == null) {
                    problems.add(Problem.of(frame, slot, where(slot, frame) + " refers to '" + r.frame()
                            + "', which is not defined."));
                } else if (instanceOf != null && !view.isA(target, instanceOf)) {
                    problems.add(Problem.of(frame, slot, where(slot, frame) + " must hold an instance of '"
                            + instanceOf + "', but '" + r.frame() + "' is not one."));
                }
            }
            case Value.Lst l -> {
                for (Value i : l.items()) {
                    checkRefs(frame, slot, i, instanceOf);
                }
            }
            default -> { }
        }
    }

    private void requireClass(String frame, String slot, String cls) {
        if (view.knownClass(cls) != null) {
            return;
        }
        Frame c = view.get(cls);
        if (c == null) {
            problems.add(Problem.of(frame, slot, where(slot, frame) + " names class '" + cls
                    + "' as its ARGUMENT, which is not defined."));
        } else if (!c.isClass()) {
            problems.add(Problem.of(frame, slot, where(slot, frame) + " names '" + cls
                    + "' as its ARGUMENT, which is an instance, not a class."));
        }
    }

    /**
     * What is known of the class named {@code name} in the view, worked out (and remembered, as any check does) when
     * it is not known yet; null when the view has no class of that name or its IS-A chain has a cycle.
     */
    ClassInfo classInfo(String name) {
        return view.classInfo(name);
    }

    private void requireFrame(String frame, String target, String relation) {
        if (view.get(target) == null) {
            problems.add(Problem.of(frame, "Frame '" + frame + "' " + relation + " '" + target
                    + "', which is not defined."));
        }
    }

    /** Names a slot in problem messages. */
    private static String where(String slot, String frame) {
        return "Slot '" + slot + "' of frame '" + frame + "'";
    }

    private List<String> childrenInView(String name, Node node) {
        List<String> kids = List.of();
        if (node != null && node.children != null && !node.children.isEmpty()) {
            kids = new ArrayList<>();
            for (Node c : node.children) {
                if (!staged.containsKey(c.name())) {
                    kids.add(c.name());
                }
            }
        }
        List<String> more = stagedChildren == null ? null : stagedChildren.get(name);
        if (more != null) {
            kids = new ArrayList<>(kids);
            kids.addAll(more);
        }
        return kids;
    }

    private static String quoteList(List<String> names) {
        List<String> shown = names.stream().limit(5).map(n -> "'" + n + "'").toList();
        return String.join(", ", shown) + (names.size() > 5 ? " and " + (names.size() - 5) + " more" : "");
    }
}
