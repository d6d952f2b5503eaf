package org.kicnp.core.xml;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.kicnp.core.Condition;
import org.kicnp.core.ConditionParser;
import org.kicnp.core.ConditionSyntaxException;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameKind;
import org.kicnp.core.InvalidFrameException;
import org.kicnp.core.Provenance;
import org.kicnp.core.Relation;
import org.kicnp.core.SemanticLink;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * Maps a {@link FrameElement} to a {@link Frame}: parses booleans, types, values and conditions, and reports each
 * thing it cannot map at the element that says it. Checks that need other frames (parents, argument classes) are
 * left to the knowledge base's batch validation; only an untyped slot's type is looked up elsewhere.
 */
final class FrameMapper {

    /** Finds how a slot is declared on a frame or above it. */
    interface TypeLookup {
        /** The type of the nearest declaration of the slot at or above the frame. */
        Optional<DataType> declaredType(String frame, String slot);

        /** The nearest ARGUMENT given for the slot at or above the frame. */
        Optional<String> declaredArgument(String frame, String slot);
    }

    private static final List<DataType> TYPES = List.of(DataType.values());

    private final Interner interner;
    private final TypeLookup types;
    private final List<LoadError> errors;
    private String source;
    /** The frame being mapped, once its NAME is read, and the slot being mapped: what each error is about. */
    private String frameName;
    private String slotName;

    FrameMapper(Interner interner, TypeLookup types, List<LoadError> errors) {
        this.interner = interner;
        this.types = types;
        this.errors = errors;
    }

    /** Maps the frame, or answers empty after adding what is wrong to the errors. */
    Optional<Frame> map(FrameElement e) {
        source = e.location().source();
        frameName = null;
        slotName = null;
        int before = errors.size();
        Optional<Located> nameItem = e.present(FrameTag.NAME);
        if (nameItem.isEmpty()) {
            error(e.location(), "A FRAME needs a NAME.");
            return Optional.empty();
        }
        String name = interner.intern(nameItem.get().stripped());
        frameName = name;
        boolean instance = flag(e.items().get(FrameTag.ISINSTANCE), new Owner(name, null), "ISINSTANCE", false);
        Frame.Builder b = Frame.builder(name, instance ? FrameKind.INSTANCE : FrameKind.CLASS);
        e.present(FrameTag.ISA).ifPresent(p -> b.parent(interner.intern(p.stripped())));
        boolean learned = flag(e.items().get(FrameTag.LEARNED), new Owner(name, null), "LEARNED", false);
        boolean runtime = flag(e.items().get(FrameTag.RUNTIME), new Owner(name, null), "RUNTIME", false);
        if (learned && runtime) {
            error(e.items().get(FrameTag.RUNTIME).at(source), "Frame '" + name + "' cannot be both LEARNED and RUNTIME.");
        }
        b.provenance(runtime ? Provenance.RUNTIME : learned ? Provenance.LEARNED : Provenance.DECLARED);
        e.present(FrameTag.PRIORITY).ifPresent(p -> {
            try {
                b.priority(Integer.parseInt(p.stripped()));
            } catch (NumberFormatException x) {
                error(p.at(source), "The PRIORITY of frame '" + name + "' is '" + p.stripped() + "', which is "
                        + (p.stripped().matches("[+-]?[0-9]+") ? "outside the range of a priority (" + Integer.MIN_VALUE
                                + " to " + Integer.MAX_VALUE + ")." : "not a whole number."));
            }
        });
        e.present(FrameTag.HASPART).ifPresent(p -> names(p, "HASPART", "PART").forEach(b::part));
        for (LinkElement l : e.linksTo()) {
            link(name, l, "SEMANTICLINKTO").ifPresent(lk -> b.linkTo(lk.relation(), lk.frame()));
        }
        for (LinkElement l : e.linksFrom()) {
            link(name, l, "SEMANTICLINKFROM").ifPresent(lk -> b.linkFrom(lk.relation(), lk.frame()));
        }
        // Loops and nulls rather than Optionals, lambdas and a set per frame: this runs for every slot of a load.
        List<SlotElement> slotElements = e.slots();
        String[] slotNames = new String[slotElements.size()];
        int named = 0;
        for (SlotElement s : slotElements) {
            Slot slot = slot(name, e, s);
            if (slot == null) {
                continue;
            }
            if (indexOf(slotNames, named, slot.name()) < 0) {
                slotNames[named++] = slot.name();
                b.slot(slot);
            } else {
                errors.add(LoadError.at(slotAt(s), "Frame '" + name + "' has a second slot named '" + slot.name()
                        + "'; slot names must be unique within a frame.", name, slot.name()));
            }
        }
        if (errors.size() > before) {
            return Optional.empty();
        }
        try {
            return Optional.of(b.build());
        } catch (InvalidFrameException x) {
            error(nameItem.get().at(source), x.getMessage());
            return Optional.empty();
        }
    }

    private static int indexOf(String[] names, int count, String name) {
        for (int i = 0; i < count; i++) {
            if (names[i].equals(name)) {
                return i;
            }
        }
        return -1;
    }

    private Optional<SemanticLink> link(String frame, LinkElement l, String list) {
        SourceLocation at = new SourceLocation(source, l.line(), l.column());
        if (l.target().isEmpty() || l.target().get().absent()) {
            error(at, "A LINK in " + list + " of frame '" + frame + "' needs a TARGET.");
            return Optional.empty();
        }
        if (l.relation().isEmpty() || l.relation().get().absent()) {
            error(at, "A LINK in " + list + " of frame '" + frame + "' needs a RELATION (SYNCHRONIZATION, "
                    + "SUCCESSION, RESTRICTION or a name of your own).");
            return Optional.empty();
        }
        Relation r = Relation.parse(l.relation().get().stripped());
        return Optional.of(new SemanticLink(r, interner.intern(l.target().get().stripped())));
    }

    /** The slot, or null after adding what is wrong to the errors. */
    private Slot slot(String frame, FrameElement fe, SlotElement s) {
        Optional<Located> nameItem = s.present(SlotTag.NAME);
        if (nameItem.isEmpty()) {
            error(slotAt(s), "A SLOT of frame '" + frame + "' needs a NAME.");
            return null;
        }
        String name = interner.intern(nameItem.get().stripped());
        Owner where = new Owner(frame, name);
        slotName = name;
        try {
            return slot(fe, s, name, where);
        } finally {
            slotName = null;
        }
    }

    private Slot slot(FrameElement fe, SlotElement s, String name, Owner where) {
        int before = errors.size();
        DataType type = type(fe, s, name, where);
        if (type == null) {
            return null;
        }
        // Plain null checks rather than Optional chains: this runs for every slot of a load, and each capturing
        // lambda is an allocation.
        Slot.Builder b = Slot.builder(name, type);
        Located argumentItem = given(s, SlotTag.ARGUMENT);
        Optional<String> argument = argumentItem == null ? Optional.empty()
                : Optional.of(interner.intern(argumentItem.stripped()));
        if (argumentItem != null) {
            b.argument(argument.get());
        }
        Located conditionItem = given(s, SlotTag.CONDITION);
        if (conditionItem != null) {
            condition(conditionItem, where).ifPresent(b::condition);
        }
        Located value = present(s, SlotTag.VALUE, type);
        Located dflt = present(s, SlotTag.DEFAULT, type);
        // A list's items take the type its ARGUMENT names; a slot that gives none inherits the nearest one above, as
        // the knowledge base's declarations do (an instance's face list of its class's TYPE_FLOAT items).
        Optional<String> itemArgument = argument;
        if (type == DataType.LIST && argument.isEmpty() && (value != null || dflt != null)) {
            itemArgument = fe.present(FrameTag.ISA).flatMap(p -> types.declaredArgument(p.stripped(), name));
        }
        if (value != null && dflt != null) {
            error(dflt.at(source), where + " has both a VALUE and a DEFAULT; the paper allows one or the other "
                    + "(Table 2).");
        } else if (value != null) {
            Value v = value(value, type, itemArgument, where, "VALUE");
            if (v != null) {
                b.value(v);
            }
        } else if (dflt != null) {
            Value v = value(dflt, type, itemArgument, where, "DEFAULT");
            if (v != null) {
                b.defaultValue(v);
            }
        }
        b.required(flag(s.get(SlotTag.REQUIRED), where, "REQUIRED", false));
        b.shared(flag(s.get(SlotTag.SHARED), where, "SHARED", true));
        b.unique(flag(s.get(SlotTag.UNIQUE), where, "UNIQUE", false));
        b.reactive(flag(s.get(SlotTag.REACTIVE), where, "REACTIVE", true));
        Located l;
        if ((l = given(s, SlotTag.ROLE)) != null) {
            b.role(interner.intern(l.stripped()));
        }
        if ((l = given(s, SlotTag.FROM)) != null) {
            b.from(interner.intern(l.stripped()));
        }
        if ((l = given(s, SlotTag.FRAMERELATED)) != null) {
            b.frameRelated(interner.intern(l.stripped()));
        }
        if ((l = given(s, SlotTag.FRAMELISTRELATED)) != null) {
            b.frameListRelated(names(l, "FRAMELISTRELATED", "ITEM"));
        }
        if ((l = given(s, SlotTag.ONNEEDED)) != null) {
            b.onNeeded(l.text());
        }
        if ((l = given(s, SlotTag.ONADDED)) != null) {
            b.onAdded(l.text());
        }
        if ((l = given(s, SlotTag.ONREMOVED)) != null) {
            b.onRemoved(l.text());
        }
        if (errors.size() > before) {
            return null;
        }
        try {
            return b.build();
        } catch (InvalidFrameException x) {
            error(slotAt(s), x.getMessage());
            return null;
        }
    }

    /** A VALUE or DEFAULT that says something, or null; for a list, {@code []} says "the empty list". */
    private static Located present(SlotElement s, SlotTag tag, DataType type) {
        Located l = s.get(tag);
        if (l == null) {
            return null;
        }
        if (type == DataType.LIST && l.items().isEmpty() && l.stripped().equals("[]")) {
            return l;
        }
        return l.absent() ? null : l;
    }

    /** The facet if it is given and not empty or NULL, else null. */
    private static Located given(SlotElement s, SlotTag tag) {
        Located l = s.get(tag);
        return l == null || l.absent() ? null : l;
    }

    private DataType type(FrameElement fe, SlotElement s, String name, Owner where) {
        Optional<Located> t = s.present(SlotTag.TYPE);
        if (t.isPresent()) {
            Optional<DataType> parsed = dataType(t.get().stripped());
            if (parsed.isEmpty()) {
                error(t.get().at(source), where + " has TYPE '" + t.get().stripped() + "', which is not a data type; "
                        + "use TYPE_INSTANCE, TYPE_STR, TYPE_INT, TYPE_FLOAT, TYPE_BOOL, TYPE_FRAME or TYPE_LIST.");
                return null;
            }
            return parsed.get();
        }
        Optional<DataType> inherited = fe.present(FrameTag.ISA)
                .flatMap(p -> types.declaredType(p.stripped(), name));
        if (inherited.isEmpty()) {
            error(slotAt(s), where + " has no TYPE, and no frame above it declares a slot '" + name + "'.");
            return null;
        }
        return inherited.get();
    }

    /** {@link DataType#parse}, with a quick path for the XML names the writer uses. */
    static Optional<DataType> dataType(String text) {
        for (DataType d : TYPES) {
            if (d.xmlName().equals(text)) {
                return Optional.of(d);
            }
        }
        return DataType.parse(text);
    }

    private Optional<Condition> condition(Located c, Owner where) {
        try {
            return Optional.of(ConditionParser.parse(c.text()));
        } catch (ConditionSyntaxException x) {
            error(conditionAt(c, x.column()), where + ": " + x.getMessage());
            return Optional.empty();
        }
    }

    /** The place in the file of character {@code column} (1-based) of the condition after leading blanks. */
    private SourceLocation conditionAt(Located c, int column) {
        if (c.textColumn() <= 0) {
            return c.at(source);
        }
        String raw = c.text();
        int lead = 0;
        while (lead < raw.length() && Character.isWhitespace(raw.charAt(lead))) {
            lead++;
        }
        int target = Math.min(raw.length(), lead + column - 1);
        int line = c.textLine();
        int col = c.textColumn();
        for (int i = 0; i < target; i++) {
            if (raw.charAt(i) == '\n') {
                line++;
                col = 1;
            } else {
                col++;
            }
        }
        return new SourceLocation(source, line, col);
    }

    /** The value, or null after reporting why it does not fit. */
    private Value value(Located v, DataType type, Optional<String> argument, Owner where, String what) {
        try {
            if (type == DataType.LIST) {
                if (v.items().isEmpty() && !v.stripped().equals("[]")) {
                    throw new IllegalArgumentException("A list value is written as ITEM elements, not as text.");
                }
                DataType itemType = argument.map(a -> dataType(a).orElse(DataType.INSTANCE))
                        .orElse(DataType.STRING);
                List<Value> items = new ArrayList<>(v.items().size());
                for (Located item : v.items()) {
                    items.add(item(itemType, item));
                }
                return new Value.Lst(items);
            }
            if (!v.items().isEmpty()) {
                throw new IllegalArgumentException("ITEM elements are only for TYPE_LIST slots.");
            }
            return scalar(type, v);
        } catch (IllegalArgumentException x) {
            error(v.at(source), where + " has a " + what + " that does not fit its type " + type.xmlName() + ": "
                    + x.getMessage());
            return null;
        }
    }

    /**
     * An item of a list: a scalar of the list's item type, or, in a list of text (TYPE_STR items, or no ARGUMENT) or of
     * lists (ARGUMENT TYPE_LIST), a list itself — ITEMs inside the ITEM, or {@code []} (not in CDATA) for the empty
     * list — whose items are read the same way.
     */
    private Value item(DataType itemType, Located item) {
        boolean nests = itemType == DataType.STRING || itemType == DataType.LIST;
        if (!item.items().isEmpty()) {
            if (!nests) {
                throw new IllegalArgumentException("an item holds ITEMs (a list inside a list), which only a list of "
                        + "TYPE_STR or TYPE_LIST items may hold, not one of " + itemType.xmlName() + ".");
            }
            List<Value> inner = new ArrayList<>(item.items().size());
            for (Located i : item.items()) {
                inner.add(item(itemType, i));
            }
            return new Value.Lst(inner);
        }
        if (nests && !item.literal() && item.stripped().equals("[]")) {
            return new Value.Lst(List.of());
        }
        return scalar(itemType == DataType.LIST ? DataType.STRING : itemType, item);
    }

    private Value scalar(DataType type, Located v) {
        return switch (type) {
            case STRING -> new Value.Str(v.text().length() <= 16 ? interner.intern(v.text()) : v.text());
            case INSTANCE, FRAME -> Value.ref(interner.intern(v.stripped()));
            case LIST -> throw new IllegalArgumentException("lists inside lists are not supported.");
            default -> Value.parse(type, v.stripped());
        };
    }

    private List<String> names(Located l, String tag, String child) {
        if (l.items().isEmpty()) {
            error(l.at(source), tag + " lists its frames as " + child + " elements, not as text.");
            return List.of();
        }
        List<String> out = new ArrayList<>(l.items().size());
        for (Located item : l.items()) {
            if (item.absent()) {
                error(item.at(source), "An empty " + child + " in " + tag + "; give a frame name.");
            } else {
                out.add(interner.intern(item.stripped()));
            }
        }
        return out;
    }

    /** Reads TRUE/FALSE (any case), or the words of the paper's Table 3 ("Checked", "No"); absent gives the default. */
    private boolean flag(Located l, Owner owner, String tag, boolean dflt) {
        if (l == null || l.absent()) {
            return dflt;
        }
        String t = l.stripped();
        if (t.equalsIgnoreCase("TRUE")) {
            return true;
        }
        if (t.equalsIgnoreCase("FALSE")) {
            return false;
        }
        return switch (t.toUpperCase(Locale.ROOT)) {
            case "TRUE", "CHECKED", "YES", "\u2713", "\u2714" -> true;
            case "FALSE", "NO", "UNCHECKED" -> false;
            default -> {
                error(l.at(source), owner + " has " + tag + " '" + l.stripped()
                        + "', which is not a boolean; write TRUE or FALSE.");
                yield dflt;
            }
        };
    }

    private SourceLocation slotAt(SlotElement s) {
        return new SourceLocation(source, s.line(), s.column());
    }

    private void error(SourceLocation at, String message) {
        errors.add(LoadError.at(at, message, frameName, slotName));
    }

    /** The frame or slot an error is about; its text is only built when an error is reported. */
    private record Owner(String frame, String slot) {
        @Override public String toString() {
            return slot == null ? "Frame '" + frame + "'" : "Slot '" + slot + "' of frame '" + frame + "'";
        }
    }
}
