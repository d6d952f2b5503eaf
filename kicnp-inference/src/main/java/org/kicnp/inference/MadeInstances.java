package org.kicnp.inference;

import java.util.ArrayDeque;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.NameTable;

/**
 * The instances the engine makes: their names ({@code Frame-N} with the engine's counter) and, between a firing's
 * addition and the knowledge-base event that reports it, their records, so that the event finds its record without a
 * look-up by name (events come in the order of the additions). Owned by the engine thread.
 */
final class MadeInstances {
    /** A short cut only: past this many records awaiting their events, the oldest are forgotten and looked up. */
    private static final int MAX_AWAITING = 4_096;
    private final KnowledgeBase kb;
    private final ArrayDeque<FactView.Fact> awaitingEvent = new ArrayDeque<>();
    private long counter;
    /** {@link NameTable#numberOf} of the last name made, known from the counter without reading the name. */
    private int number = -1;

    MadeInstances(KnowledgeBase kb) {
        this(kb, 0);
    }

    /** Counting on from {@code counter} (tests: names with many digits). */
    MadeInstances(KnowledgeBase kb, long counter) {
        this.kb = kb;
        this.counter = counter;
    }

    /**
     * The next name for an instance of {@code prefix}. Whether a frame of that name exists already is found by the
     * knowledge base when the instance is added (the firing then takes the next name), so the usual case costs no
     * look-up.
     */
    String next(String prefix) {
        counter++;
        // "prefix-N" ends in N after its last '-': a number when N has at most nine digits and the prefix is not empty.
        number = counter <= 999_999_999 && !prefix.isEmpty() ? (int) counter : -1;
        return prefix + "-" + counter;
    }

    /** The number the last name made ends in, as {@link NameTable#numberOf} reads it off the name. */
    int number() {
        return number;
    }

    /** The next name that no frame has now (for instances that scripts create). */
    String fresh(String prefix) {
        String n;
        do {
            n = next(prefix);
        } while (kb.contains(n));
        return n;
    }

    /** Notes the record of an instance the engine has just added. */
    void added(FactView.Fact made) {
        if (awaitingEvent.size() >= MAX_AWAITING) {
            awaitingEvent.clear();
        }
        awaitingEvent.add(made);
    }

    /** The record of the instance an Added event reports, when the engine made it; else null (look it up). */
    FactView.Fact take(Frame added) {
        FactView.Fact head = awaitingEvent.peekFirst();
        return head != null && head.name.equals(added.name()) ? awaitingEvent.pollFirst() : null;
    }
}
