package org.kicnp.core.xml;

import java.util.EnumMap;
import java.util.List;
import java.util.Optional;
import org.kicnp.core.DataType;

/**
 * A FRAME element as read, before mapping: its simple items by tag, its links and slots, where it starts, and whether
 * reading it found structural mistakes (unknown, repeated or misplaced elements, which are skipped), so that what was
 * read may not be all the frame says.
 */
record FrameElement(SourceLocation location, EnumMap<FrameTag, Located> items, List<LinkElement> linksTo,
        List<LinkElement> linksFrom, List<SlotElement> slots, boolean damaged) {

    /** The item if it is given and not empty or NULL. */
    Optional<Located> present(FrameTag tag) {
        Located l = items.get(tag);
        return l == null || l.absent() ? Optional.empty() : Optional.of(l);
    }

    /** The stripped NAME text, or empty when the frame has none. */
    Optional<String> name() {
        return present(FrameTag.NAME).map(Located::stripped);
    }

    /**
     * Whether the frame can be mapped without looking at other frames: every slot names its TYPE, and no list value
     * takes its item type from an ARGUMENT above the frame (the declarations it inherits may come later).
     */
    boolean selfTyped() {
        boolean hasParent = present(FrameTag.ISA).isPresent();
        for (SlotElement s : slots) {
            Optional<Located> type = s.present(SlotTag.TYPE);
            if (type.isEmpty()) {
                return false;
            }
            if (hasParent && s.present(SlotTag.ARGUMENT).isEmpty() && (s.get(SlotTag.VALUE) != null
                    || s.get(SlotTag.DEFAULT) != null) && FrameMapper.dataType(type.get().stripped())
                    .filter(t -> t == DataType.LIST).isPresent()) {
                return false;
            }
        }
        return true;
    }
}
