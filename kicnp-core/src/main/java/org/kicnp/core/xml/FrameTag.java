package org.kicnp.core.xml;

import java.util.List;

/** The simple child elements of FRAME; SLOTLIST and the two link lists are read separately. */
enum FrameTag {
    NAME, ISA, ISINSTANCE, DESCENDANTS("FRAME", "ITEM"), HASPART("PART"), LEARNED, RUNTIME, PRIORITY;

    private final List<String> childTags;

    FrameTag(String... childTags) {
        this.childTags = List.of(childTags);
    }

    /** The element names allowed inside this one. */
    List<String> childTags() {
        return childTags;
    }

    static FrameTag of(String tag) {
        return switch (tag) {
            case "NAME" -> NAME;
            case "ISA" -> ISA;
            case "ISINSTANCE" -> ISINSTANCE;
            case "DESCENDANTS" -> DESCENDANTS;
            case "HASPART" -> HASPART;
            case "LEARNED" -> LEARNED;
            case "RUNTIME" -> RUNTIME;
            case "PRIORITY" -> PRIORITY;
            default -> null;
        };
    }
}
