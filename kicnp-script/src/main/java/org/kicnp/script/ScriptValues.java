package org.kicnp.script;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.graalvm.polyglot.Value;
import org.graalvm.polyglot.proxy.Proxy;

/**
 * Converts between plain Java values and what scripts see.
 *
 * <p>To Java ({@link #toJava}): {@code null} and {@code undefined} become {@link Undefined#INSTANCE}; booleans
 * {@link Boolean}; strings {@link String}; numbers a {@link Long} when integral and within range (so {@code 3.0}
 * gives {@code 3L}), else a {@link Double}; arrays an unmodifiable {@link List}; other objects an unmodifiable
 * insertion-ordered {@link Map} of their own enumerable members; a proxy built by {@link Proxies} the Java value
 * it was built from; another proxy or a host object itself; a {@code Date} an {@link java.time.Instant};
 * anything else (functions, symbols) its JavaScript text. No polyglot {@link Value} is returned, so results
 * stay valid after the context that produced them is reused or closed.
 */
public final class ScriptValues {

    private static final int MAX_DEPTH = 64;

    private ScriptValues() {
    }

    /** Converts a script value to plain Java, as described on the class. */
    public static Object toJava(Value value) {
        return toJava(value, 0);
    }

    /**
     * Converts a Java value to what a script sees: strings, booleans and boxed numbers as they are
     * ({@code BigDecimal}/{@code BigInteger} as doubles, characters as strings); maps and lists through
     * {@link Proxies#object}/{@link Proxies#array}; knowledge-core values by their type ({@code Ref} as the frame
     * name); {@link Optional} by its content; {@link Undefined} or {@code null} as {@code null}; proxies and
     * polyglot values unchanged; any other object as a host object, of which scripts can use only members
     * annotated {@code @HostAccess.Export}.
     */
    public static Object toGuest(Object value) {
        return switch (value) {
            case null -> null;
            case Undefined u -> null;
            case String s -> s;
            case Boolean b -> b;
            case Character c -> c.toString();
            case BigDecimal d -> d.doubleValue();
            case BigInteger i -> i.bitLength() < 64 ? (Object) i.longValue() : (Object) i.doubleValue();
            case Number n -> n;
            case Optional<?> o -> toGuest(o.orElse(null));
            case org.kicnp.core.Value v -> fromCore(v);
            case ScriptObject o -> Proxies.lazy(o);
            case Map<?, ?> m -> Proxies.object(stringKeys(m));
            case List<?> l -> Proxies.array(l);
            case Collection<?> c -> Proxies.array(List.copyOf(c));
            case Proxy p -> p;
            case Value v -> v;
            default -> value;
        };
    }

    private static Object fromCore(org.kicnp.core.Value value) {
        return switch (value) {
            case org.kicnp.core.Value.Str s -> s.value();
            case org.kicnp.core.Value.Int i -> i.value();
            case org.kicnp.core.Value.Real r -> r.value();
            case org.kicnp.core.Value.Bool b -> b.value();
            case org.kicnp.core.Value.Ref r -> r.frame();
            case org.kicnp.core.Value.Lst l -> Proxies.array(l.items());
        };
    }

    private static Map<String, ?> stringKeys(Map<?, ?> map) {
        Map<String, Object> out = new LinkedHashMap<>();
        map.forEach((k, v) -> out.put(String.valueOf(k), v));
        return out;
    }

    private static Object toJava(Value value, int depth) {
        if (depth > MAX_DEPTH) {
            throw new IllegalArgumentException("The script result is nested deeper than " + MAX_DEPTH
                    + " levels or refers to itself, so it cannot be converted to Java.");
        }
        if (value.isNull()) {
            return Undefined.INSTANCE;
        }
        if (value.isBoolean()) {
            return value.asBoolean();
        }
        if (value.isString()) {
            return value.asString();
        }
        if (value.isNumber()) {
            return value.fitsInLong() ? (Object) value.asLong() : (Object) value.asDouble();
        }
        if (value.isProxyObject()) {
            Proxy proxy = value.asProxyObject();
            return proxy instanceof Proxies.Unwrappable u ? u.javaValue() : proxy;
        }
        if (value.isHostObject()) {
            return value.asHostObject();
        }
        if (value.hasArrayElements()) {
            List<Object> list = new ArrayList<>((int) Math.min(value.getArraySize(), 1024));
            for (long i = 0; i < value.getArraySize(); i++) {
                list.add(toJava(value.getArrayElement(i), depth + 1));
            }
            return Collections.unmodifiableList(list);
        }
        if (value.isInstant()) {
            return value.asInstant();
        }
        if (value.canExecute() || !value.hasMembers()) {
            return value.toString();
        }
        Map<String, Object> map = new LinkedHashMap<>();
        for (String key : value.getMemberKeys()) {
            map.put(key, toJava(value.getMember(key), depth + 1));
        }
        return Collections.unmodifiableMap(map);
    }
}
