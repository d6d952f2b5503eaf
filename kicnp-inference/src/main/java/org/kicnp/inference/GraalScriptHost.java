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
 *
 * <p>Host functions are bound only for scripts whose text names them (as a whole identifier): binding and unbinding
 * a global costs about as much as running a short script, and the engine offers nine of them. A script therefore
 * cannot reach a host function through a name computed at run time ({@code globalThis['send' + 'msg']}).
 * {@code s} and every non-function global are always bound.
 */
public final class GraalScriptHost implements ScriptHost {
    private final ScriptRuntime runtime;

    public GraalScriptHost(ScriptRuntime runtime) {
        this.runtime = requireNonNull(runtime, "runtime");
    }

    /** Runs the script; a result of {@code undefined} or {@code null} comes back as Java {@code null}. */
    @Override public Object run(String frame, String slot, String source, Map<String, Object> globals) {
        Object result = runtime.run(compile(frame, slot, source), adapt(source, globals));
        return result == ScriptRuntime.UNDEFINED ? null : result;
    }

    @Override public boolean test(String frame, String slot, String source, Map<String, Object> globals) {
        return runtime.test(compile(frame, slot, source), adapt(source, globals));
    }

    /** Parses the script into the runtime's cache, under the id its runs use; a syntax error is left to its run. */
    @Override public void prepare(String frame, String slot, String source) {
        try {
            compile(frame, slot, source);
        } catch (RuntimeException e) {
            // A script that does not parse (or a runtime closed meanwhile): its run reports it, with the firing.
        }
    }

    private CompiledScript compile(String frame, String slot, String source) {
        return runtime.compile(new ScriptId(frame, slot), source);
    }

    private static Map<String, Object> adapt(String source, Map<String, Object> globals) {
        Map<String, Object> out = new LinkedHashMap<>();
        globals.forEach((k, v) -> {
            if (!(v instanceof HostFunction f)) {
                out.put(k, v);
            } else if (names(source, k)) {
                out.put(k, Proxies.function(f::call));
            }
        });
        return out;
    }

    /** Whether the source contains the name as a whole identifier (not inside a longer one such as {@code xsendmsg}). */
    static boolean names(String source, String name) {
        for (int at = source.indexOf(name); at >= 0; at = source.indexOf(name, at + 1)) {
            int end = at + name.length();
            if ((at == 0 || !identifierPart(source.charAt(at - 1)))
                    && (end == source.length() || !identifierPart(source.charAt(end)))) {
                return true;
            }
        }
        return false;
    }

    private static boolean identifierPart(char c) {
        return Character.isJavaIdentifierPart(c);
    }
}
