package org.kicnp.editor;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.SemanticLink;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * Renames a frame as one knowledge-base batch: add the frame under its new name, rewrite every reference to the
 * old name in other frames (A-kind-of, has-part, semantic links, slot arguments, values, defaults, related
 * frames), remove the old frame. The batch applies all or nothing, so a rename that would break a rule changes
 * nothing. Names inside JavaScript and condition text are not rewritten: they are code, not references.
 */
final class Renamer {
    private final String from;
    private final String to;

    private Renamer(String from, String to) {
        this.from = from;
        this.to = to;
    }

    /** The changes that rename {@code from} to {@code to} in {@code kb}, read from its current frames. */
    static List<Change> changes(KnowledgeBase kb, String from, String to) {
        Frame old = kb.require(from);
        Renamer r = new Renamer(from, to);
        List<Change> changes = new ArrayList<>();
        changes.add(new Change.Add(r.rewrite(old, to)));
        for (Frame f : kb.frames()) {
            if (!f.name().equals(from)) {
                Frame rewritten = r.rewrite(f, f.name());
                if (!rewritten.equals(f)) {
                    changes.add(new Change.Replace(rewritten));
                }
            }
        }
        changes.add(new Change.Remove(from));
        return changes;
    }

    private Frame rewrite(Frame f, String newName) {
        Frame.Builder b = Frame.builder(newName, f.kind()).provenance(f.provenance()).priority(f.priority());
        f.parent().map(this::name).ifPresent(b::parent);
        f.parts().forEach(p -> b.part(name(p)));
        for (SemanticLink l : f.linksTo()) {
            b.linkTo(l.relation(), name(l.frame()));
        }
        for (SemanticLink l : f.linksFrom()) {
            b.linkFrom(l.relation(), name(l.frame()));
        }
        f.slots().forEach(s -> b.slot(rewrite(s)));
        return b.build();
    }

    private Slot rewrite(Slot s) {
        Slot.Builder b = s.toBuilder();
        s.argument().map(this::name).ifPresent(b::argument);
        s.frameRelated().map(this::name).ifPresent(b::frameRelated);
        b.frameListRelated(s.frameListRelated().stream().map(this::name).toList());
        s.value().map(this::rewrite).ifPresent(b::value);
        s.defaultValue().map(this::rewrite).ifPresent(b::defaultValue);
        return b.build();
    }

    private Value rewrite(Value v) {
        return switch (v) {
            case Value.Ref r -> Value.ref(name(r.frame()));
            case Value.Lst l -> new Value.Lst(l.items().stream().map(this::rewrite).toList());
            default -> v;
        };
    }

    private String name(String n) {
        return Objects.equals(n, from) ? to : n;
    }
}
