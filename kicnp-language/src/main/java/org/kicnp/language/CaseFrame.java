package org.kicnp.language;

import static java.util.Objects.requireNonNull;

import java.util.Collections;
import java.util.EnumMap;
import java.util.Map;
import java.util.Optional;

/**
 * One parsed utterance: its act (with the predicate in {@link Case#ACTION} where a verb was said), the cases that
 * were expressed and what fills them, whether it corrects what the speaker said before ("No, coffee please",
 * "Actually, make it tea"), and the text as said. Only what was said is there: an implied case stays absent.
 */
public record CaseFrame(Act act, Map<Case, Filler> cases, boolean correction, String text) {
    public CaseFrame {
        requireNonNull(act, "act");
        requireNonNull(text, "text");
        EnumMap<Case, Filler> copy = new EnumMap<>(Case.class);
        copy.putAll(requireNonNull(cases, "cases"));
        for (Case c : copy.keySet()) {
            if (!act.cases().contains(c)) {
                throw new IllegalArgumentException("A case frame of act '" + act + "' has no case '" + c + "'.");
            }
        }
        cases = Collections.unmodifiableMap(copy);
    }

    /** The filler of a case, if the utterance expressed it. */
    public Optional<Filler> filler(Case c) {
        return Optional.ofNullable(cases.get(c));
    }

    /** The normalised value of a case, if the utterance expressed it. */
    public Optional<String> value(Case c) {
        return filler(c).map(Filler::value);
    }

    /** True unless some filler is a noun the lexicon does not know. */
    public boolean allKnown() {
        return cases.values().stream().allMatch(Filler::known);
    }
}
