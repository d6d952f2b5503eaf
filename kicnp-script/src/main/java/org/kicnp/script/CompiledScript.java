package org.kicnp.script;

import static java.util.Objects.requireNonNull;

import org.graalvm.polyglot.Source;

/**
 * A script that parsed: its id, its text as written, and the cached source the shared engine runs. Obtained
 * from {@link ScriptRuntime#compile} and only usable with the runtime that compiled it.
 */
public final class CompiledScript {
    private final ScriptId id;
    private final String text;
    private final Source source;
    private final ScriptRuntime owner;

    CompiledScript(ScriptId id, String text, Source source, ScriptRuntime owner) {
        this.id = requireNonNull(id, "id");
        this.text = requireNonNull(text, "text");
        this.source = requireNonNull(source, "source");
        this.owner = requireNonNull(owner, "owner");
    }

    /** The frame and slot the script comes from. */
    public ScriptId id() {
        return id;
    }

    /** The script text as given to {@link ScriptRuntime#compile}, before quote normalisation. */
    public String text() {
        return text;
    }

    Source source() {
        return source;
    }

    ScriptRuntime owner() {
        return owner;
    }

    @Override public String toString() {
        return "CompiledScript[" + id + "]";
    }
}
