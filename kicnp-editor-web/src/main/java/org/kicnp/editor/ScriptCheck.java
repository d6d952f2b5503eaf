package org.kicnp.editor;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.LinkedHashMap;
import java.util.Map;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptId;
import org.kicnp.script.ScriptRuntime;
import org.kicnp.script.ScriptSyntaxException;

/**
 * Checks a script's syntax with the platform's own JavaScript runtime, so the page can refuse to save a script that
 * would not parse. Only compiles, never runs: nothing the script says is executed. The runtime is created on the
 * first check (starting GraalJS takes a moment) and closed with the editor.
 */
final class ScriptCheck implements Features.Scripts, AutoCloseable {
    static final int MAX_SOURCE = 256 * 1024;

    private ScriptRuntime runtime;

    @Override public boolean available() {
        return true;
    }

    @Override public Object check(JsonNode body) {
        String source = body.hasNonNull("source") ? body.get("source").asText() : "";
        String name = FrameInput.text(body, "name").orElse("editor.script");
        if (source.length() > MAX_SOURCE) {
            throw new ApiException(413, "A script may be at most " + MAX_SOURCE + " characters long.");
        }
        int dot = name.indexOf('.');
        ScriptId id = dot > 0 ? new ScriptId(name.substring(0, dot), name.substring(dot + 1)) : new ScriptId(name, "script");
        Map<String, Object> out = new LinkedHashMap<>();
        try {
            runtime().compile(id, source);
            out.put("ok", true);
            out.put("message", "The script parses.");
            out.put("line", 0);
            out.put("column", 0);
        } catch (ScriptSyntaxException e) {
            out.put("ok", false);
            out.put("message", e.parserMessage());
            out.put("line", e.line());
            out.put("column", e.column());
        }
        return out;
    }

    private synchronized ScriptRuntime runtime() {
        if (runtime == null) {
            runtime = ScriptRuntime.create(ScriptConfig.defaults());
        }
        return runtime;
    }

    @Override public synchronized void close() {
        if (runtime != null) {
            runtime.close();
            runtime = null;
        }
    }
}
