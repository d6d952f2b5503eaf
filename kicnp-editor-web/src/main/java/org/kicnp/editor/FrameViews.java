package org.kicnp.editor;

import java.util.ArrayList;
import java.util.List;
import org.kicnp.core.EffectiveSlot;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.SemanticLink;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * The JSON shapes the API answers with, and their mapping from the domain types. Domain types carry no Jackson
 * annotations; these records are the editor's wire format and are documented in {@code docs/editor-openapi.yaml}.
 * Absent facets are written as JSON {@code null}.
 */
final class FrameViews {
    private FrameViews() {
    }

    /**
     * A row of {@code GET /api/frames}. {@code links} are the semantic links the frame declares (both its "to" and
     * its "from" items) as directed arrows, so the page can draw every link of the hierarchy from the listing alone.
     */
    record Summary(String name, String kind, String parent, boolean learned, String provenance, long revision,
            int slotCount, boolean hasLinks, List<Arrow> links) {
    }

    /**
     * A semantic link as an arrow: the relation's name, the frame it goes out of and the frame it goes into. A
     * frame's "to" link {@code (R, X)} is {@code self -> X}; its "from" link {@code (R, X)} is {@code X -> self}.
     */
    record Arrow(String relation, String from, String to) {
    }

    /** A semantic link: the relation's name and the frame at the other end. */
    record Link(String relation, String frame) {
    }

    /** A direct sub-frame, for the descendants item of Table 1. */
    record Child(String name, String kind) {
    }

    /** Every facet of Table 2, plus demons and the reactive flag. Values are text, lists are arrays of text. */
    record SlotView(String name, String role, String from, String type, Object value, Object defaultValue,
            String condition, String argument, boolean required, boolean shared, boolean unique,
            String frameRelated, List<String> frameListRelated, String onNeeded, String onAdded, String onRemoved,
            boolean reactive) {
    }

    /** A slot as the frame sees it after inheritance, and where it comes from. */
    record EffectiveSlotView(SlotView slot, String declaredBy, String valueFrom, boolean inherited) {
    }

    /** The answer of {@code GET /api/frames/{name}}. */
    record Detail(String name, String kind, String parent, String provenance, boolean learned, int priority,
            long revision, List<String> ancestors, List<Child> children, List<String> parts, List<Link> linksTo,
            List<Link> linksFrom, List<Link> linksOut, List<Link> linksIn, List<SlotView> slots,
            List<EffectiveSlotView> effectiveSlots) {
    }

    static Summary summary(KnowledgeBase kb, Frame f) {
        return new Summary(f.name(), f.kind().name(), f.parent().orElse(null), f.learned(), f.provenance().name(),
                kb.revision(f.name()), f.slots().size(), !f.linksTo().isEmpty() || !f.linksFrom().isEmpty(),
                arrows(f));
    }

    /** The frame's declared links as arrows: its "to" links first, then its "from" links, each in declared order. */
    static List<Arrow> arrows(Frame f) {
        List<Arrow> out = new ArrayList<>(f.linksTo().size() + f.linksFrom().size());
        for (SemanticLink l : f.linksTo()) {
            out.add(new Arrow(l.relation().name(), f.name(), l.frame()));
        }
        for (SemanticLink l : f.linksFrom()) {
            out.add(new Arrow(l.relation().name(), l.frame(), f.name()));
        }
        return List.copyOf(out);
    }

    static Detail detail(KnowledgeBase kb, Frame f) {
        String n = f.name();
        List<EffectiveSlotView> effective = kb.slots(n).stream().map(e -> effective(n, e)).toList();
        return new Detail(n, f.kind().name(), f.parent().orElse(null), f.provenance().name(), f.learned(),
                f.priority(), kb.revision(n), kb.ancestors(n),
                kb.children(n).stream().map(c -> new Child(c.name(), c.kind().name())).toList(), f.parts(),
                links(f.linksTo()), links(f.linksFrom()), links(kb.linksOutOf(n)), links(kb.linksInto(n)),
                f.slots().stream().map(FrameViews::slot).toList(), effective);
    }

    static EffectiveSlotView effective(String frame, EffectiveSlot e) {
        return new EffectiveSlotView(slot(e.slot()), e.declaredBy(), e.valueFrom(), e.inheritedBy(frame));
    }

    static SlotView slot(Slot s) {
        return new SlotView(s.name(), s.role().orElse(null), s.from().orElse(null), s.type().xmlName(),
                s.value().map(FrameViews::value).orElse(null), s.defaultValue().map(FrameViews::value).orElse(null),
                s.condition().text(), s.argument().orElse(null), s.required(), s.shared(), s.unique(),
                s.frameRelated().orElse(null), s.frameListRelated(), s.onNeeded().orElse(null),
                s.onAdded().orElse(null), s.onRemoved().orElse(null), s.reactive());
    }

    static List<Link> links(List<SemanticLink> links) {
        return links.stream().map(l -> new Link(l.relation().name(), l.frame())).toList();
    }

    /** A scalar as its text; a list as a JSON array of its items' texts. */
    static Object value(Value v) {
        return switch (v) {
            case Value.Lst l -> l.items().stream().map(Value::text).toList();
            default -> v.text();
        };
    }
}
