package org.kicnp.script;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;

import org.graalvm.polyglot.Value;
import org.graalvm.polyglot.proxy.ProxyArray;
import org.graalvm.polyglot.proxy.ProxyExecutable;
import org.graalvm.polyglot.proxy.ProxyObject;

/**
 * Builds the objects scripts see: read-only objects and arrays from Java maps and lists, and functions from
 * Java lambdas. These are proxies, not host objects, so they expose exactly what the caller put in them and
 * nothing of the Java classes behind.
 */
public final class Proxies {

    private Proxies() {
    }

    /**
     * A read-only object whose members are the map's entries, converted once with {@link ScriptValues#toGuest}
     * (nested maps become nested objects, lists become arrays). Assigning to a member fails in the script.
     */
    public static ProxyObject object(Map<String, ?> members) {
        requireNonNull(members, "members");
        Map<String, Object> converted = new LinkedHashMap<>();
        members.forEach((k, v) -> converted.put(requireNonNull(k, "member name"), ScriptValues.toGuest(v)));
        return new ReadOnlyObject(Collections.unmodifiableMap(converted), members);
    }

    /** A read-only object whose members are read from {@code source} when first asked for, then kept for the run. */
    public static ProxyObject lazy(ScriptObject source) {
        return new LazyObject(requireNonNull(source, "source"), new HashMap<>());
    }

    /** A read-only array of the list's elements, converted once with {@link ScriptValues#toGuest}. */
    public static ProxyArray array(List<?> elements) {
        requireNonNull(elements, "elements");
        List<Object> converted = new ArrayList<>(elements.size());
        elements.forEach(e -> converted.add(ScriptValues.toGuest(e)));
        return new ReadOnlyArray(Collections.unmodifiableList(converted), elements);
    }

    /** A function scripts can call; arguments are converted to plain Java and the result back to JavaScript. */
    public static ProxyExecutable function(ScriptFunction function) {
        requireNonNull(function, "function");
        return arguments -> {
            List<Object> args = new ArrayList<>(arguments.length);
            for (Value argument : arguments) {
                args.add(ScriptValues.toJava(argument));
            }
            return ScriptValues.toGuest(function.call(Collections.unmodifiableList(args)));
        };
    }

    /** A function returning {@code undefined}, for host actions such as {@code Sendmsg}. */
    public static ProxyExecutable procedure(Consumer<List<Object>> procedure) {
        requireNonNull(procedure, "procedure");
        return function(arguments -> {
            procedure.accept(arguments);
            return Undefined.INSTANCE;
        });
    }

    /** A proxy that can give back the Java value it was built from, so results convert to plain Java. */
    interface Unwrappable {
        Object javaValue();
    }

    /** What both object proxies share: no member can be set or removed, and each unwraps to its source. */
    private interface ReadOnlyProxy extends ProxyObject, Unwrappable {
        Object source();

        @Override default void putMember(String key, Value value) {
            throw new UnsupportedOperationException("The object is read-only; member '" + key + "' cannot be set.");
        }

        @Override default boolean removeMember(String key) {
            throw new UnsupportedOperationException("The object is read-only; member '" + key + "' cannot be removed.");
        }

        @Override default Object javaValue() {
            return source();
        }
    }

    private record ReadOnlyObject(Map<String, Object> members, Map<String, ?> source) implements ReadOnlyProxy {

        @Override public Object getMember(String key) {
            return members.get(key);
        }

        @Override public Object getMemberKeys() {
            return ProxyArray.fromArray(members.keySet().toArray());
        }

        @Override public boolean hasMember(String key) {
            return members.containsKey(key);
        }

        @Override public String toString() {
            return "ReadOnlyObject" + members.keySet();
        }
    }

    private record LazyObject(ScriptObject source, Map<String, Optional<Object>> read) implements ReadOnlyProxy {

        private Optional<Object> read(String key) {
            Optional<Object> v = read.get(key);
            if (v == null) {
                v = source.member(key).map(ScriptValues::toGuest);
                read.put(key, v);
            }
            return v;
        }

        @Override public Object getMember(String key) {
            return read(key).orElse(null);
        }

        @Override public Object getMemberKeys() {
            return ProxyArray.fromArray(source.memberKeys().toArray());
        }

        @Override public boolean hasMember(String key) {
            return read(key).isPresent();
        }

        @Override public String toString() {
            return "read-only object";
        }
    }

    private record ReadOnlyArray(List<Object> elements, List<?> source) implements ProxyArray, Unwrappable {

        @Override public Object get(long index) {
            if (index < 0 || index >= elements.size()) {
                throw new ArrayIndexOutOfBoundsException("Index " + index + " is outside the array of " + elements.size() + ".");
            }
            return elements.get((int) index);
        }

        @Override public void set(long index, Value value) {
            throw new UnsupportedOperationException("The array is read-only; element " + index + " cannot be set.");
        }

        @Override public boolean remove(long index) {
            throw new UnsupportedOperationException("The array is read-only; element " + index + " cannot be removed.");
        }

        @Override public long getSize() {
            return elements.size();
        }

        @Override public Object javaValue() {
            return source;
        }

        @Override public String toString() {
            return "ReadOnlyArray" + elements;
        }
    }
}
