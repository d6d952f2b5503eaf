package org.kicnp.core;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * The scripts a frame holds, each with the phrase that names it in a message: the paper's procedural slots
 * ({@code onInstantiate}, {@code onDestroy}: string slots whose value is a script), the FRL demons of each slot
 * ({@code onNeeded}, {@code onAdded}, {@code onRemoved}) and {@code js:} conditions. What checks them (the editor
 * before a save, {@code kicnp validate} after a load) reads them from here, so both name the same scripts alike.
 */
public final class FrameScripts {
    /** The paper's procedural slots: string slots whose value is a script. */
    public static final List<String> PROCEDURAL = List.of("onInstantiate", "onDestroy");

    /** One non-blank script of a frame: its slot, the phrase naming it ("The onAdded demon of slot …") and its text. */
    public record Script(Slot slot, String what, String source) {
    }

    private FrameScripts() {
    }

    /** The frame's non-blank scripts, slot by slot in the frame's order. */
    public static List<Script> of(Frame frame) {
        List<Script> out = new ArrayList<>();
        String f = frame.name();
        for (Slot s : frame.slots()) {
            String of = " of slot '" + s.name() + "' of frame '" + f + "'";
            if (PROCEDURAL.contains(s.name()) && s.type() == DataType.STRING) {
                add(out, s, "The script in slot '" + s.name() + "' of frame '" + f + "'",
                        s.effectiveValue().map(Value::text));
            }
            add(out, s, "The onNeeded demon" + of, s.onNeeded());
            add(out, s, "The onAdded demon" + of, s.onAdded());
            add(out, s, "The onRemoved demon" + of, s.onRemoved());
            if (s.condition() instanceof Condition.Script c) {
                add(out, s, "The js: condition" + of, Optional.of(c.source()));
            }
        }
        return out;
    }

    private static void add(List<Script> out, Slot slot, String what, Optional<String> source) {
        source.filter(t -> !t.isBlank()).ifPresent(t -> out.add(new Script(slot, what, t)));
    }
}
