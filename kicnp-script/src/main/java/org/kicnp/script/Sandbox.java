package org.kicnp.script;

import java.io.OutputStream;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.Set;

import org.graalvm.polyglot.Context;
import org.graalvm.polyglot.Engine;
import org.graalvm.polyglot.EnvironmentAccess;
import org.graalvm.polyglot.HostAccess;
import org.graalvm.polyglot.PolyglotAccess;
import org.graalvm.polyglot.ResourceLimits;
import org.graalvm.polyglot.io.IOAccess;

/**
 * The permissions of a script context, built explicitly rather than from a preset: no file system, processes,
 * threads, native code, environment, other languages or class loading; Java only through members annotated
 * {@code @HostAccess.Export} and the public members of allow-listed classes, which are also the only names
 * {@code Java.type} can look up.
 */
final class Sandbox {
    private final Engine engine;
    private final HostAccess hostAccess;
    private final Set<String> allowedClasses;
    private final ResourceLimits limits;
    private final OutputStream out;
    private final OutputStream err;

    Sandbox(Engine engine, ScriptConfig config, OutputStream out, OutputStream err) {
        this.engine = engine;
        this.allowedClasses = config.allowedHostClasses();
        this.hostAccess = hostAccess(allowedClasses);
        // One limits instance for every context: the engine shares code between contexts with equal limits.
        this.limits = ResourceLimits.newBuilder().statementLimit(config.statementLimit(), null).build();
        this.out = out;
        this.err = err;
    }

    /**
     * A fresh context with the sandbox's permissions, bound to the shared engine. JavaScript is initialised here,
     * so that setting up the realm is not charged to the time limit of the first script run in the context.
     */
    Context newContext() {
        Context context = Context.newBuilder("js")
                .engine(engine)
                .allowHostAccess(hostAccess)
                .allowHostClassLookup(allowedClasses::contains)
                .allowHostClassLoading(false)
                .allowIO(IOAccess.NONE)
                .allowCreateProcess(false)
                .allowCreateThread(false)
                .allowNativeAccess(false)
                .allowEnvironmentAccess(EnvironmentAccess.NONE)
                .allowPolyglotAccess(PolyglotAccess.NONE)
                .allowInnerContextOptions(false)
                .allowExperimentalOptions(false)
                .resourceLimits(limits)
                .out(out)
                .err(err)
                .build();
        context.initialize("js");
        return context;
    }

    private static HostAccess hostAccess(Set<String> allowedClasses) {
        HostAccess.Builder builder = HostAccess.newBuilder()
                .allowAccessAnnotatedBy(HostAccess.Export.class)
                .allowImplementationsAnnotatedBy(HostAccess.Implementable.class)
                .allowPublicAccess(false)
                .allowAllImplementations(false)
                .allowAllClassImplementations(false)
                .allowArrayAccess(false)
                .allowListAccess(false)
                .allowMapAccess(false)
                .allowIterableAccess(false)
                .allowIteratorAccess(false)
                .allowBufferAccess(false)
                .allowAccessInheritance(false);
        for (String name : allowedClasses) {
            allowMembers(builder, load(name));
        }
        return builder.build();
    }

    private static Class<?> load(String name) {
        try {
            return Class.forName(name, false, Sandbox.class.getClassLoader());
        } catch (ClassNotFoundException e) {
            throw new IllegalArgumentException("The allow-listed script class '" + name + "' does not exist.", e);
        }
    }

    private static void allowMembers(HostAccess.Builder builder, Class<?> type) {
        if (!Modifier.isPublic(type.getModifiers())) {
            throw new IllegalArgumentException("The allow-listed script class '" + type.getName() + "' is not public.");
        }
        for (Method method : type.getMethods()) {
            if (method.getDeclaringClass() != Object.class) {
                builder.allowAccess(method);
            }
        }
        for (Field field : type.getFields()) {
            builder.allowAccess(field);
        }
        for (Constructor<?> constructor : type.getConstructors()) {
            builder.allowAccess(constructor);
        }
    }
}
