package org.kicnp.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.kicnp.core.Condition;
import org.kicnp.core.DataType;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.core.xml.LoadError;
import org.kicnp.core.xml.SourceLocation;
import org.kicnp.core.xml.SourcedFrame;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptId;
import org.kicnp.script.ScriptRuntime;
import org.kicnp.script.ScriptSyntaxException;

/**
 * Parses every script of the frames with the platform's JavaScript runtime, as the editor does before saving, so that
 * {@code validate} reports a script that would not parse instead of leaving it to fail at every firing. Only compiles,
 * never runs. The scripts are the paper's procedural slots ({@code onInstantiate}, {@code onDestroy}), the demons
 * ({@code onNeeded}, {@code onAdded}, {@code onRemoved}) and {@code js:} conditions.
 */
final class ScriptSyntaxCheck {
    private static final List<String> PROCEDURAL = List.of("onInstantiate", "onDestroy");

    /** A script's text, the phrase naming it in a message, and the frame it came with. */
    private record Source(String frame, String slot, String what, String text, SourcedFrame where) {
    }

    private ScriptSyntaxCheck() {
    }

    /** One error per script that does not parse, placed at its FRAME's start tag. */
    static List<LoadError> errors(List<SourcedFrame> frames) {
        List<Source> sources = new ArrayList<>();
        for (SourcedFrame sf : frames) {
            String f = sf.frame().name();
            for (Slot s : sf.frame().slots()) {
                String of = " of slot '" + s.name() + "' of frame '" + f + "'";
                if (PROCEDURAL.contains(s.name()) && s.type() == DataType.STRING) {
                    add(sources, s, "The script in slot '" + s.name() + "' of frame '" + f + "'",
                            s.effectiveValue().map(Value::text), sf);
                }
                add(sources, s, "The onNeeded demon" + of, s.onNeeded(), sf);
                add(sources, s, "The onAdded demon" + of, s.onAdded(), sf);
                add(sources, s, "The onRemoved demon" + of, s.onRemoved(), sf);
                if (s.condition() instanceof Condition.Script c) {
                    add(sources, s, "The js: condition" + of, Optional.of(c.source()), sf);
                }
            }
        }
        List<LoadError> errors = new ArrayList<>();
        if (sources.isEmpty()) {
            return errors;
        }
        try (ScriptRuntime runtime = ScriptRuntime.create(ScriptConfig.defaults())) {
            for (Source s : sources) {
                try {
                    runtime.compile(new ScriptId(s.frame(), s.slot()), s.text());
                } catch (ScriptSyntaxException e) {
                    SourceLocation at = s.where().location();
                    errors.add(new LoadError(at.source(), at.line(), at.column(), s.what() + " has a syntax error at line "
                            + e.line() + ", column " + e.column() + ": " + e.parserMessage() + ".",
                            Optional.of(s.frame()), Optional.of(s.slot())));
                }
            }
        }
        return errors;
    }

    private static void add(List<Source> sources, Slot slot, String what, Optional<String> text, SourcedFrame where) {
        text.filter(t -> !t.isBlank()).ifPresent(t -> sources.add(new Source(where.frame().name(), slot.name(), what, t,
                where)));
    }
}
