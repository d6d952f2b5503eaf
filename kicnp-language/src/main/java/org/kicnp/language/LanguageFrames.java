package org.kicnp.language;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Slot;

/**
 * The class frames of what users say: the root {@code Utterance} (text, speaker, correction, known), one subclass
 * per {@link Act} with a STRING slot per case it may carry, and {@code SaidUnknown} for what was not understood.
 * The same frames are in {@code org/kicnp/language/language.xml} in the paper's format; a test keeps the two equal.
 */
public final class LanguageFrames {
    /** The root class of every parsed utterance. */
    public static final String ROOT = "Utterance";
    /** The class of sentences that were not understood. */
    public static final String UNKNOWN = "SaidUnknown";
    /** The classpath resource holding the same frames as XML. */
    public static final String RESOURCE = "/org/kicnp/language/language.xml";

    private static final Map<String, String> ROOT_SLOTS = slots(
            "text", "the sentence as said",
            "speaker", "the agent (user, or Robovie's microphone) that said it",
            "correction", "true if it corrects what the speaker said before (No, coffee please)",
            "known", "false if some noun is not in the lexicon (I'd like a lemonade)");

    private LanguageFrames() {
    }

    /** The root, one class per act in the order of {@link Act}, then {@code SaidUnknown}. */
    public static List<Frame> classes() {
        List<Frame> out = new ArrayList<>();
        Frame.Builder root = Frame.classFrame(ROOT);
        ROOT_SLOTS.forEach((name, role) -> root.slot(slot(name, role)));
        out.add(root.build());
        for (Act act : Act.values()) {
            Frame.Builder b = Frame.classFrame(act.className()).parent(ROOT);
            for (Case c : Case.values()) {
                if (act.cases().contains(c)) {
                    b.slot(slot(act.slotFor(c), "the " + c.name().toLowerCase(java.util.Locale.ROOT).replace('_', '-')
                            + " case"));
                }
            }
            out.add(b.build());
        }
        out.add(Frame.classFrame(UNKNOWN).parent(ROOT)
                .slot(slot("reason", "why the parser did not understand"))
                .slot(slot("reply", "what to say to the speaker")).build());
        return List.copyOf(out);
    }

    private static Slot slot(String name, String role) {
        return Slot.builder(name, DataType.STRING).role(role).build();
    }

    private static Map<String, String> slots(String... nameRole) {
        Map<String, String> m = new LinkedHashMap<>();
        for (int i = 0; i < nameRole.length; i += 2) {
            m.put(nameRole[i], nameRole[i + 1]);
        }
        return m;
    }
}
