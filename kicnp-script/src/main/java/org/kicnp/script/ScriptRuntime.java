package org.kicnp.script;

import static java.util.Objects.requireNonNull;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Pattern;

import org.graalvm.polyglot.Context;
import org.graalvm.polyglot.Engine;
import org.graalvm.polyglot.PolyglotException;
import org.graalvm.polyglot.Source;
import org.graalvm.polyglot.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The JavaScript runtime: compiles slot scripts once and runs them in sandboxed, time-bounded contexts.
 *
 * <p>All contexts share one polyglot {@link Engine}, so a script parsed once is reused by every context. Contexts
 * come from a pool; a run owns its context until it ends, so any number of threads may call {@link #run} at once
 * without sharing a context. Every run has a statement limit and a wall-clock limit (see {@link ScriptConfig}).
 *
 * <p>A script is run as a program and its <em>completion value</em> is the result: for an expression such as
 * {@code s.mUser.age > 3} that is the expression's value, for statements such as {@code Sendmsg(s.mMouth, "Hi");}
 * the value of the last expression statement. The text is run inside a block, so its {@code let}/{@code const}
 * declarations are local to the run (a leading {@code 'use strict'} directive is kept in force); {@code var} and function declarations become globals of the pooled context
 * and scripts must not rely on them. {@code return} is not allowed at top level. Typographic quotes used as
 * string delimiters are turned into ASCII ones first (see {@code QuoteNormalizer}).
 *
 * <p>Results are converted with {@link ScriptValues#toJava}: no polyglot value escapes, and JavaScript
 * {@code null}/{@code undefined} become {@link #UNDEFINED}, never a Java {@code null}.
 */
public final class ScriptRuntime implements AutoCloseable {

    /** The result of a script whose completion value is {@code undefined} or {@code null}. */
    public static final Undefined UNDEFINED = Undefined.INSTANCE;

    private static final int CACHE_SIZE = 4096;
    /** A leading "use strict" directive, which must stay outside the block the text runs in to take effect. */
    private static final Pattern STRICT = Pattern.compile("\\s*(?://[^\\n]*\\n\\s*|/\\*.*?\\*/\\s*)*(['\"])use strict\\1",
            Pattern.DOTALL);

    private static final Logger LOG = LoggerFactory.getLogger(ScriptRuntime.class);

    private final ScriptConfig config;
    private final Engine engine;
    private final ContextPool pool;
    private final Watchdog watchdog;
    private final Map<Key, CompiledScript> cache;
    private final AtomicLong parses = new AtomicLong();
    private volatile boolean closed;

    private ScriptRuntime(ScriptConfig config) {
        this.config = config;
        this.engine = Engine.newBuilder("js")
                .option("engine.WarnInterpreterOnly", "false")
                .out(new ScriptOutput(false))
                .err(new ScriptOutput(true))
                .logHandler(new EngineLog())
                .build();
        this.pool = new ContextPool(new Sandbox(engine, config, new ScriptOutput(false), new ScriptOutput(true)),
                config.maxIdleContexts());
        this.watchdog = new Watchdog(Watchdog.tickFor(config.timeLimit()));
        this.cache = Collections.synchronizedMap(new LinkedHashMap<>(64, 0.75f, true) {
            @Override protected boolean removeEldestEntry(Map.Entry<Key, CompiledScript> eldest) {
                return size() > CACHE_SIZE;
            }
        });
    }

    /** Starts a runtime with the given limits and allow-list; close it to release the engine and its threads. */
    public static ScriptRuntime create(ScriptConfig config) {
        ScriptRuntime runtime = new ScriptRuntime(requireNonNull(config, "config"));
        runtime.warmUp();
        LOG.debug("Script runtime started on {} ({}).", runtime.engine.getImplementationName(),
                runtime.compilerEnabled() ? "Graal compiler enabled" : "interpreter only");
        return runtime;
    }

    /**
     * Whether scripts are compiled to machine code by the Graal compiler ({@code false} when the JVM was started
     * without it and GraalJS only interprets; docs/scripting.md says how to enable it).
     */
    public boolean compilerEnabled() {
        return !"Interpreted".equalsIgnoreCase(engine.getImplementationName());
    }

    /** The polyglot engine's implementation name, for diagnostics ({@code Interpreted} without the compiler). */
    public String engineName() {
        return engine.getImplementationName();
    }

    /** The configuration this runtime enforces. */
    public ScriptConfig config() {
        return config;
    }

    /**
     * Parses a script, or returns the script compiled earlier from the same id and text. Use it to check a script
     * before saving it: a script that does not parse throws {@link ScriptSyntaxException} with line and column.
     */
    public CompiledScript compile(ScriptId id, String text) {
        requireNonNull(id, "id");
        requireNonNull(text, "text");
        ensureOpen();
        Key key = new Key(id, text);
        CompiledScript cached = cache.get(key);
        if (cached != null) {
            return cached;
        }
        CompiledScript fresh = parse(id, text);
        CompiledScript raced = cache.putIfAbsent(key, fresh);
        return raced != null ? raced : fresh;
    }

    /**
     * Runs a script with the given globals bound (each converted with {@link ScriptValues#toGuest}) and returns
     * its completion value as plain Java. Throws {@link ScriptFailedException} when the script throws and
     * {@link ScriptTimeoutException} when it overruns a limit; the runtime stays usable in both cases.
     */
    public Object run(CompiledScript script, Map<String, ?> globals) {
        requireNonNull(script, "script");
        requireNonNull(globals, "globals");
        if (script.owner() != this) {
            throw new IllegalArgumentException("The script " + script.id() + " was compiled by another script runtime.");
        }
        ensureOpen();
        Context context = pool.acquire();
        boolean reusable = false;
        Watchdog.Guard guard = null;
        try {
            context.resetLimits();
            Value bindings = context.getBindings("js");
            globals.forEach((name, value) -> bindings.putMember(name, ScriptValues.toGuest(value)));
            guard = watchdog.watch(context, config.timeLimit());
            Object result = ScriptValues.toJava(context.eval(script.source()));
            boolean inTime = guard.finish();
            reusable = inTime && unbind(bindings, globals);
            return result;
        } catch (PolyglotException e) {
            boolean stopped = guard != null && !guard.finish();
            if (stopped) {
                clearCancellationInterrupt();
            }
            reusable = !stopped && !ScriptErrors.poisons(e) && unbind(context, globals);
            throw ScriptErrors.run(script.id(), e, stopped, config);
        } catch (IllegalArgumentException | IllegalStateException e) {
            if (guard != null && !guard.finish()) {
                clearCancellationInterrupt();
                throw new ScriptTimeoutException(script.id(), ScriptTimeoutException.Limit.TIME,
                        config.timeLimit().toMillis() + " ms", e);
            }
            throw ScriptErrors.conversion(script.id(), e);
        } finally {
            if (guard != null) {
                guard.finish();
            }
            if (reusable) {
                pool.release(context);
            } else {
                pool.discard(context);
            }
        }
    }

    /** Runs a condition and returns its JavaScript truthiness ({@code false, 0, NaN, "", null, undefined} are false). */
    public boolean test(CompiledScript script, Map<String, ?> globals) {
        return truthy(run(script, globals));
    }

    /** How many times a script text was actually parsed (cache misses of {@link #compile}). */
    long parseCount() {
        return parses.get();
    }

    /** How many contexts the pool created so far. */
    int contextsCreated() {
        return pool.created();
    }

    @Override public void close() {
        if (closed) {
            return;
        }
        closed = true;
        watchdog.close();
        pool.close();
        engine.close(true);
        cache.clear();
    }

    static boolean truthy(Object value) {
        return switch (value) {
            case Boolean b -> b;
            case Long l -> l != 0;
            case Double d -> d != 0 && !d.isNaN();
            case String s -> !s.isEmpty();
            case Undefined u -> false;
            default -> true;
        };
    }

    /**
     * What a behavior script commonly does first, run once at start: the first regular expression loads and
     * initialises GraalJS's regex engine, and the first string, number, array and JSON built-ins load their classes;
     * on a cold JVM that took about 0.3 s inside the first reaction of Table 5 (the first name heard), now spent here.
     */
    static final String WARM_UP_BUILT_INS = "var t = String('My name is Ken.').replace(/[^A-Za-z0-9_]/g, '');"
            + "/^ken$/i.test(t.substring(6)); t.charAt(0).toUpperCase() + t.toLowerCase();"
            + "Number('0.25').toFixed(2) + [1, 2].join(',') + JSON.stringify({a: [1]}) + Math.max(1, 2);";

    /**
     * Pays the one-off costs (engine start, realm set-up, first proxy and host-class access, which together take
     * seconds on a cold JVM, and the built-ins of {@link #WARM_UP_BUILT_INS}) here rather than inside the time limit,
     * and the latency, of the first real script.
     */
    private void warmUp() {
        StringBuilder text = new StringBuilder("w.f(w.a + w.b.length);").append(WARM_UP_BUILT_INS);
        for (String name : config.allowedHostClasses()) {
            text.append(";Java.type('").append(name).append("')");
        }
        Source source = Source.newBuilder("js", text.toString(), "warm-up").cached(false).buildLiteral();
        Context context = pool.acquire();
        try {
            context.getBindings("js").putMember("w", Proxies.object(Map.of("a", 1, "b", java.util.List.of(1),
                    "f", Proxies.function(args -> args.get(0)))));
            context.eval(source);
            context.getBindings("js").removeMember("w");
            pool.release(context);
        } catch (PolyglotException e) {
            pool.discard(context);
            LOG.warn("Warming up the script runtime failed; the first scripts may run slowly.", e);
        }
    }

    private CompiledScript parse(ScriptId id, String text) {
        parses.incrementAndGet();
        String normalized = QuoteNormalizer.normalize(text);
        Context context = pool.acquire();
        boolean reusable = false;
        try {
            // Parsed bare first so that syntax errors point at the text as written.
            context.parse(Source.newBuilder("js", normalized, id.sourceName()).cached(false).buildLiteral());
            String prologue = STRICT.matcher(normalized).lookingAt() ? "'use strict';" : "";
            Source block = Source.newBuilder("js", prologue + "{" + normalized + "\n}", id.sourceName())
                    .cached(true).buildLiteral();
            context.parse(block);
            reusable = true;
            return new CompiledScript(id, text, block, this);
        } catch (PolyglotException e) {
            if (e.isSyntaxError()) {
                reusable = true;
                throw ScriptErrors.syntax(id, text, e);
            }
            throw ScriptErrors.run(id, e, false, config);
        } finally {
            if (reusable) {
                pool.release(context);
            } else {
                pool.discard(context);
            }
        }
    }

    /**
     * Cancelling an overrunning context interrupts the thread running it, so that a host function blocked in
     * {@code sleep} or I/O returns; that interrupt was ours, not the caller's, so it must not outlive the run.
     */
    private static void clearCancellationInterrupt() {
        Thread.interrupted();
    }

    private static boolean unbind(Context context, Map<String, ?> globals) {
        try {
            return unbind(context.getBindings("js"), globals);
        } catch (RuntimeException e) {
            return false;
        }
    }

    /** Removes the run's globals; {@code false} if one could not be removed and the context must be dropped. */
    private static boolean unbind(Value bindings, Map<String, ?> globals) {
        boolean clean = true;
        for (String name : globals.keySet()) {
            try {
                clean &= bindings.removeMember(name);
            } catch (RuntimeException e) {
                clean = false;
            }
        }
        return clean;
    }

    private void ensureOpen() {
        if (closed) {
            throw new IllegalStateException("The script runtime is closed.");
        }
    }

    private record Key(ScriptId id, String text) {
    }
}
