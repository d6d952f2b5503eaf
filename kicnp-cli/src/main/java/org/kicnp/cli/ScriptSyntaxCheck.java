package org.kicnp.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.kicnp.core.FrameScripts;
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
    /** A script's text, the phrase naming it in a message, and the frame it came with. */
    private record Source(String frame, String slot, String what, String text, SourcedFrame where) {
    }

    private ScriptSyntaxCheck() {
    }

    /** One error per script that does not parse, placed at its FRAME's start tag. */
    static List<LoadError> errors(List<SourcedFrame> frames) {
        List<Source> sources = new ArrayList<>();
        for (SourcedFrame sf : frames) {
            for (FrameScripts.Script script : FrameScripts.of(sf.frame())) {
                sources.add(new Source(sf.frame().name(), script.slot().name(), script.what(), script.source(), sf));
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
}
