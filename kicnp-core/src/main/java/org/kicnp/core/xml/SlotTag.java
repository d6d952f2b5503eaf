package org.kicnp.core.xml;

import java.util.List;

/** The child elements of SLOT: the facets of Table 2, the demons and the reactive flag. */
enum SlotTag {
    NAME, ROLE, FROM, TYPE, CONDITION, ARGUMENT, VALUE("ITEM"), DEFAULT("ITEM"), REQUIRED, SHARED, UNIQUE,
    FRAMERELATED, FRAMELISTRELATED("ITEM"), ONNEEDED, ONADDED, ONREMOVED, REACTIVE;

    /** How many tags there are. */
    static final int COUNT = values().length;

    private final List<String> childTags;

    SlotTag(String... childTags) {
        this.childTags = List.of(childTags);
    }

    /** The element names allowed inside this one. */
    List<String> childTags() {
        return childTags;
    }

    static SlotTag of(String tag) {
        return switch (tag) {
            case "NAME" -> NAME;
            case "ROLE" -> ROLE;
            case "FROM" -> FROM;
            case "TYPE" -> TYPE;
            case "CONDITION" -> CONDITION;
            case "ARGUMENT" -> ARGUMENT;
            case "VALUE" -> VALUE;
            case "DEFAULT" -> DEFAULT;
            case "REQUIRED" -> REQUIRED;
            case "SHARED" -> SHARED;
            case "UNIQUE" -> UNIQUE;
            case "FRAMERELATED" -> FRAMERELATED;
            case "FRAMELISTRELATED" -> FRAMELISTRELATED;
            case "ONNEEDED" -> ONNEEDED;
            case "ONADDED" -> ONADDED;
            case "ONREMOVED" -> ONREMOVED;
            case "REACTIVE" -> REACTIVE;
            default -> null;
        };
    }
}
