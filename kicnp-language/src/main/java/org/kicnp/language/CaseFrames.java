package org.kicnp.language;

import static java.util.Objects.requireNonNull;

import java.util.Map;
import java.util.Optional;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * The bridge to the knowledge base: a case frame becomes a RUNTIME instance of its act's class
 * ({@code SaidName}, {@code SaidDrinkRequest}, {@code SaidCommand}, {@code SaidYesNo}, {@code SaidHello}), with one
 * STRING slot per case holding the filler's normalised value, plus {@code text}, {@code correction}, {@code known}
 * and, when given, {@code speaker}. Behaviour frames match these with slot conditions such as {@code == "tea"}.
 */
public final class CaseFrames {
    private CaseFrames() {
    }

    /** The instance for a case frame, without a speaker. */
    public static Frame toFrame(CaseFrame frame, String instanceName) {
        return toFrame(frame, instanceName, Optional.empty());
    }

    /** The instance for a case frame said by {@code speaker} (an agent name). */
    public static Frame toFrame(CaseFrame frame, String instanceName, String speaker) {
        return toFrame(frame, instanceName, Optional.of(requireNonNull(speaker, "speaker")));
    }

    private static Frame toFrame(CaseFrame frame, String instanceName, Optional<String> speaker) {
        requireNonNull(frame, "frame");
        Frame.Builder b = base(instanceName, frame.act().className(), frame.text(), speaker)
                .slot(str("correction", String.valueOf(frame.correction())))
                .slot(str("known", String.valueOf(frame.allKnown())));
        for (Map.Entry<Case, Filler> e : frame.cases().entrySet()) {
            b.slot(str(frame.act().slotFor(e.getKey()), e.getValue().value()));
        }
        return b.build();
    }

    /** The instance of {@code SaidUnknown} for a sentence that was not understood. */
    public static Frame unknown(ParseResult.NotUnderstood result, String text, String instanceName, String speaker) {
        requireNonNull(result, "result");
        return base(instanceName, LanguageFrames.UNKNOWN, requireNonNull(text, "text"),
                Optional.of(requireNonNull(speaker, "speaker")))
                .slot(str("correction", "false"))
                .slot(str("reason", result.reason()))
                .slot(str("reply", result.reply())).build();
    }

    private static Frame.Builder base(String instanceName, String className, String text, Optional<String> speaker) {
        Frame.Builder b = Frame.instance(requireNonNull(instanceName, "instanceName"), className)
                .provenance(Provenance.RUNTIME)
                .slot(str("text", text));
        speaker.ifPresent(s -> b.slot(str("speaker", s)));
        return b;
    }

    private static Slot str(String name, String value) {
        return Slot.ofValue(name, DataType.STRING, Value.of(value));
    }
}
