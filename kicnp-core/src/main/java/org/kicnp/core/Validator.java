package org.kicnp.core;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Function;

/**
 * Checks a staged batch against the knowledge base as it would be after the batch ({@code view}), collecting every
 * problem rather than stopping at the first. Reads only; the knowledge base applies the batch if nothing is found.
 */
final class Validator {
    private final Function<String, Frame> view;
    private final Map<String, Frame> staged;
    private final Map<String, Node> base;
    private final List<Problem> problems = new ArrayList<>();
    /** Per class name: the slot declarations it inherits and makes (see {@link #declarations}). */
    private final Map<String, Map<String, Declaration>> declared = new HashMap<>();
    /** Frames whose IS-A chain has been walked to its root without a cycle. */
    private final Set<String> acyclic = new HashSet<>();

    /**
     * @param staged touched names to their frame after the batch, or null where the batch removes the frame
     * @param base the knowledge base's nodes before the batch
     */
    Validator(Map<String, Frame> staged, Map<String, Node> base) {
        this.staged = staged;
        this.base = base;
        this.view = name -> {
            Frame f = staged.get(name);
            if (f != null || staged.containsKey(name)) {
                return f;
            }
            Node n = base.get(name);
            return n == null ? null : n.frame;
        };
    }

    Function<String, Frame> view() {
        return view;
    }

    List<Problem> validate(Map<String, List<String>> stagedChildren) {
        for (Map.Entry<String, Frame> e : staged.entrySet()) {
            if (e.getValue() == null) {
                checkRemoval(e.getKey(), stagedChildren);
            } else {
                checkFrame(e.getValue(), stagedChildren);
            }
        }
        return problems;
    }

    private void checkRemoval(String name, Map<String, List<String>> stagedChildren) {
        Node node = base.get(name);
        List<String> kids = childrenInView(name, node, stagedChildren);
        if (!kids.isEmpty()) {
            boolean instances = kids.stream().map(view).allMatch(Frame::isInstance);
            problems.add(Problem.of(name, "Frame '" + name + "' cannot be removed: it still has "
                    + (instances ? "instances " : "subclasses or instances ") + quoteList(kids) + "."));
        }
        if (node != null && node.referrers != null) {
            for (String r : node.referrers) {
                if (!staged.containsKey(r)) {
                    problems.add(Problem.of(name, "Frame '" + name + "' cannot be removed: frame '" + r
                            + "' refers to it."));
                }
            }
        }
    }

    private void checkFrame(Frame f, Map<String, List<String>> stagedChildren) {
        String name = f.name();
        if (f.parent().isPresent()) {
            String p = f.parent().get();
            Frame parent = view.apply(p);
            if (parent == null) {
                problems.add(Problem.of(name, "Frame '" + name + "' is a kind of '" + p + "', which is not defined."));
                return;
            }
            if (parent.isInstance()) {
                problems.add(Problem.of(name, "Frame '" + name + "' is a kind of '" + p
                        + "', which is an instance; only classes can have sub-frames."));
                return;
            }
            if (hasCycle(f)) {
                problems.add(Problem.of(name, "Frame '" + name + "' is a kind of '" + p
                        + "', which makes an IS-A cycle: " + cycleText(f) + "."));
                return;
            }
        }
        if (f.isInstance()) {
            List<String> kids = childrenInView(name, base.get(name), stagedChildren);
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
        Map<String, Declaration> inheritedSlots = f.parent().isPresent() && !f.slots().isEmpty()
                ? declarations(f.parent().get()) : Map.of();
        for (Slot s : f.slots()) {
            checkSlot(f, s, inheritedSlots);
        }
        if (f.provenance().durable()) {
            checkNoRuntimeReferences(f);
        }
    }

    /** A durable frame must reload on its own after a restart, when runtime frames are gone. */
    private void checkNoRuntimeReferences(Frame f) {
        f.parent().map(view).filter(p -> p.provenance() == Provenance.RUNTIME).ifPresent(p ->
                problems.add(Problem.of(f.name(), "Frame '" + f.name() + "' is kept on disk but is a kind of '"
                        + p.name() + "', which exists only at run time.")));
        for (String r : References.of(f)) {
            Frame target = view.apply(r);
            if (target != null && target.provenance() == Provenance.RUNTIME) {
                problems.add(Problem.of(f.name(), "Frame '" + f.name() + "' is kept on disk but refers to '" + r
                        + "', which exists only at run time; copy the values it needs instead."));
            }
        }
    }

    private void checkSlot(Frame f, Slot own, Map<String, Declaration> inheritedSlots) {
        String name = f.name();
        SlotRef where = new SlotRef(own.name(), name);
        Declaration inherited = inheritedSlots.get(own.name());
        Frame declaring = inherited == null ? null : inherited.declaredBy();
        Slot above = inherited == null ? null : inherited.slot();
        String inheritedArgument = inherited == null ? null : inherited.argument();
        if (above != null && above.type() != own.type()) {
            problems.add(Problem.of(name, own.name(), where + " is " + own.type().xmlName() + " but '"
                    + declaring.name() + "' declares it " + above.type().xmlName() + "."));
            return;
        }
        Optional<String> argument = own.argument().isPresent() ? own.argument() : Optional.ofNullable(inheritedArgument);
        switch (own.type()) {
            case INSTANCE -> {
                if (argument.isEmpty()) {
                    problems.add(Problem.of(name, own.name(), where
                            + " holds an instance but has no ARGUMENT naming the class it must hold."));
                    return;
                }
                requireClass(name, own.name(), where, argument.get());
            }
            case FRAME -> argument.ifPresent(a -> requireClass(name, own.name(), where, a));
            case LIST -> argument.filter(References::isClassArgument)
                    .ifPresent(a -> requireClass(name, own.name(), where, a));
            default -> { }
        }
        Optional<String> instanceOf = own.type() == DataType.INSTANCE ? argument
                : own.type() == DataType.LIST ? argument.filter(References::isClassArgument) : Optional.empty();
        own.value().ifPresent(v -> checkRefs(name, own.name(), where, v, instanceOf));
        own.defaultValue().ifPresent(v -> checkRefs(name, own.name(), where, v, instanceOf));
        own.frameRelated().ifPresent(r -> requireFrame(name, r, "names as frame-related in slot '" + own.name() + "'"));
        own.frameListRelated().forEach(r -> requireFrame(name, r,
                "names as frame-list-related in slot '" + own.name() + "'"));
        checkPaths(f, own, where);
    }

    private void checkPaths(Frame f, Slot own, SlotRef where) {
        List<Operand> operands = switch (own.condition()) {
            case Condition.Compare c -> List.of(c.right());
            case Condition.Between b -> List.of(b.low(), b.high());
            case Condition.OneOf o -> o.options();
            default -> List.of();
        };
        for (Operand o : operands) {
            if (o instanceof Operand.Path p && Inheritance.slot(view, f, p.head()).isEmpty()) {
                problems.add(Problem.of(f.name(), own.name(), where + " has a condition on '" + p.text()
                        + "', but frame '" + f.name() + "' has no slot '" + p.head() + "'."));
            }
        }
    }

    private void checkRefs(String frame, String slot, SlotRef where, Value v, Optional<String> instanceOf) {
        switch (v) {
            case Value.Ref r -> {
                Frame target = view.apply(r.frame());
                if (target == null) {
                    problems.add(Problem.of(frame, slot, where + " refers to '" + r.frame()
                            + "', which is not defined."));
                } else if (instanceOf.isPresent() && !isA(target, instanceOf.get())) {
                    problems.add(Problem.of(frame, slot, where + " must hold an instance of '" + instanceOf.get()
                            + "', but '" + r.frame() + "' is not one."));
                }
            }
            case Value.Lst l -> l.items().forEach(i -> checkRefs(frame, slot, where, i, instanceOf));
            default -> { }
        }
    }

    private boolean isA(Frame f, String ancestor) {
        int steps = 0;
        for (Frame x = f; x != null && steps++ < 100_000; x = parentOf(x)) {
            if (x.name().equals(ancestor)) {
                return true;
            }
        }
        return false;
    }

    private void requireClass(String frame, String slot, SlotRef where, String cls) {
        Frame c = view.apply(cls);
        if (c == null) {
            problems.add(Problem.of(frame, slot, where + " names class '" + cls + "' as its ARGUMENT, which is not defined."));
        } else if (!c.isClass()) {
            problems.add(Problem.of(frame, slot, where + " names '" + cls + "' as its ARGUMENT, which is an instance, not a class."));
        }
    }

    private void requireFrame(String frame, String target, String relation) {
        if (view.apply(target) == null) {
            problems.add(Problem.of(frame, "Frame '" + frame + "' " + relation + " '" + target
                    + "', which is not defined."));
        }
    }

    private boolean hasCycle(Frame f) {
        // Real hierarchies are shallow: walk without allocating, and only track names on a suspiciously long chain.
        // A chain that reaches a frame already walked without a cycle has none either.
        int steps = 0;
        for (Frame x = f; x != null; x = parentOf(x)) {
            if (acyclic.contains(x.name())) {
                break;
            }
            if (++steps > 10_000) {
                Set<String> seen = new HashSet<>();
                for (Frame y = f; y != null; y = parentOf(y)) {
                    if (!seen.add(y.name())) {
                        return true;
                    }
                }
                return false;
            }
        }
        acyclic.add(f.name());
        return false;
    }

    private Frame parentOf(Frame f) {
        return f.parent().isPresent() ? view.apply(f.parent().get()) : null;
    }

    /**
     * The slots declared on class {@code name} or above it, each with the nearest frame declaring it and the nearest
     * ARGUMENT given for it on the way up. Computed once per class and batch: the frames of a large load share few
     * parents, so this replaces a walk up the IS-A chain per slot with one lookup. The chain is known to be acyclic,
     * because a frame with a cycle above it is reported before its slots are checked.
     */
    private Map<String, Declaration> declarations(String name) {
        Map<String, Declaration> known = declared.get(name);
        if (known != null) {
            return known;
        }
        List<Frame> chain = new ArrayList<>();
        Map<String, Declaration> above = Map.of();
        for (Frame x = view.apply(name); x != null; x = parentOf(x)) {
            Map<String, Declaration> memo = declared.get(x.name());
            if (memo != null) {
                above = memo;
                break;
            }
            chain.add(x);
        }
        for (int i = chain.size() - 1; i >= 0; i--) {
            Frame x = chain.get(i);
            Map<String, Declaration> here;
            if (x.slots().isEmpty()) {
                here = above;
            } else {
                here = new HashMap<>(Math.max(16, (above.size() + x.slots().size()) * 2));
                here.putAll(above);
                for (Slot s : x.slots()) {
                    Declaration up = above.get(s.name());
                    String argument = s.argument().isPresent() ? s.argument().get()
                            : up == null ? null : up.argument();
                    here.put(s.name(), new Declaration(s, x, argument));
                }
            }
            declared.put(x.name(), here);
            above = here;
        }
        return above;
    }

    /** Names a slot in problem messages; the text is only built when a problem is reported. */
    private record SlotRef(String slot, String frame) {
        @Override public String toString() {
            return "Slot '" + slot + "' of frame '" + frame + "'";
        }
    }

    /** A slot as declared up the IS-A chain: the nearest declaration, and the nearest ARGUMENT at or above it. */
    private record Declaration(Slot slot, Frame declaredBy, String argument) {
    }

    private String cycleText(Frame f) {
        List<String> path = new ArrayList<>();
        Set<String> seen = new HashSet<>();
        Frame x = f;
        while (x != null && seen.add(x.name())) {
            path.add(x.name());
            x = x.parent().map(view).orElse(null);
        }
        if (x != null) {
            path.add(x.name());
        }
        return String.join(" -> ", path);
    }

    private List<String> childrenInView(String name, Node node, Map<String, List<String>> stagedChildren) {
        List<String> kids = new ArrayList<>();
        if (node != null && node.children != null) {
            for (Node c : node.children) {
                if (!staged.containsKey(c.name())) {
                    kids.add(c.name());
                }
            }
        }
        kids.addAll(stagedChildren.getOrDefault(name, List.of()));
        return kids;
    }

    private static String quoteList(List<String> names) {
        List<String> shown = names.stream().limit(5).map(n -> "'" + n + "'").toList();
        return String.join(", ", shown) + (names.size() > 5 ? " and " + (names.size() - 5) + " more" : "");
    }
}
