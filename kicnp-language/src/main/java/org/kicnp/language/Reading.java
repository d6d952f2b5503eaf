package org.kicnp.language;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * What the parser knows about one sentence while it reads it: the text, the expectation, the robot addressed by a
 * vocative, and whether the sentence corrects an earlier one or was polite. Owned by one parse call, never shared.
 */
final class Reading {
    final String text;
    final Expectation expectation;
    Optional<Filler> vocative = Optional.empty();
    boolean correction;
    /** "please" was said: the sentence is a request. */
    boolean polite;
    /** "thanks" or "thank you" was said. */
    boolean thanked;
    private final List<String> reasons = new ArrayList<>();
    private final List<String> weakReasons = new ArrayList<>();

    Reading(String text, Expectation expectation) {
        this.text = text;
        this.expectation = expectation;
    }

    /** Remembers why a rule could not apply; the first reason is the one reported. */
    void miss(String reason) {
        reasons.add(reason);
    }

    /** Remembers that a rule did not even start (no verb where one was looked for): reported only if nothing else is. */
    void missWeakly(String reason) {
        weakReasons.add(reason);
    }

    Optional<String> firstReason() {
        return reasons.stream().findFirst();
    }

    Optional<String> firstWeakReason() {
        return weakReasons.stream().findFirst();
    }

    /** A frame of the act with the vocative as agent (commands, requests) or recipient (everything else). */
    CaseFrame frame(Act act, Map<Case, Filler> cases) {
        Map<Case, Filler> all = new EnumMap<>(Case.class);
        all.putAll(cases);
        vocative.ifPresent(v -> {
            Case c = act == Act.ROBOT_COMMAND || act == Act.DRINK_REQUEST ? Case.AGENT : Case.RECIPIENT;
            all.put(c, v);
        });
        return new CaseFrame(act, all, correction, text);
    }
}
