package org.kicnp.editor;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameScripts;
import org.kicnp.script.ScriptConfig;
import org.kicnp.script.ScriptId;
import org.kicnp.script.ScriptRuntime;
import org.kicnp.script.ScriptSyntaxException;

/**
 * Checks a script's syntax with the platform's own JavaScript runtime, so the page can refuse to save a script that
 * would not parse, and the API refuses a frame whose scripts do not parse (its own client may skip the page's check). Only compiles, never runs: nothing the script says is executed. The runtime is created on the
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

    @Override public List<ApiProblem> problems(Frame frame) {
        List<ApiProblem> problems = new ArrayList<>();
        for (FrameScripts.Script script : FrameScripts.of(frame)) {
            try {
                runtime().compile(new ScriptId(frame.name(), script.slot().name()), script.source());
            } catch (ScriptSyntaxException e) {
                problems.add(ApiProblem.of(frame.name(), script.slot().name(), script.what() + " has a syntax error "
                        + "at line " + e.line() + ", column " + e.column() + ": " + e.parserMessage() + "."));
            }
        }
        return problems;
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
