package org.kicnp.inference;

import static java.util.Objects.requireNonNull;

import java.util.LinkedHashMap;
import java.util.Map;
import org.kicnp.script.CompiledScript;
import org.kicnp.script.Proxies;
import org.kicnp.script.ScriptId;
import org.kicnp.script.ScriptRuntime;

/**
 * The engine's scripts run by the platform's GraalJS runtime: each slot script is compiled once (cached by the
 * runtime per frame, slot and text) and run sandboxed and time-bounded; {@link HostFunction}s become JavaScript
 * functions. Syntax errors, script errors and timeouts surface as the runtime's exceptions, naming frame and slot.
 */
public final class GraalScriptHost implements ScriptHost {
    private final ScriptRuntime runtime;

    public GraalScriptHost(ScriptRuntime runtime) {
        this.runtime = requireNonNull(runtime, "runtime");
    }

    /** Runs the script; a result of {@code undefined} or {@code null} comes back as Java {@code null}. */
    @Override public Object run(String frame, String slot, String source, Map<String, Object> globals) {
        Object result = runtime.run(compile(frame, slot, source), adapt(globals));
        return result == ScriptRuntime.UNDEFINED ? null : result;
    }

    @Override public boolean test(String frame, String slot, String source, Map<String, Object> globals) {
        return runtime.test(compile(frame, slot, source), adapt(globals));
    }

    private CompiledScript compile(String frame, String slot, String source) {
        return runtime.compile(new ScriptId(frame, slot), source);
    }

    private static Map<String, Object> adapt(Map<String, Object> globals) {
        Map<String, Object> out = new LinkedHashMap<>();
        globals.forEach((k, v) -> out.put(k, v instanceof HostFunction f ? Proxies.function(f::call) : v));
        return out;
    }
}
