package org.kicnp.inference;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;

/**
 * A short collection in insertion order kept in one field, with no object of its own while it is short: the field
 * holds null (empty), the one element itself, an {@code Object[]} of at most {@value #SMALL} elements padded with
 * trailing nulls, or, past that, a {@link LinkedHashSet} (so that removal stays cheap where a fact takes part in many
 * bindings). The static methods take the field's value and return its new value. Elements are never null, and never
 * an array or a collection themselves (the engine's are activations, binding keys, names and fact records), so the
 * field's class tells its form.
 *
 * <p>The one-element form: most bags hold one element all their life (a key's bucket in an alpha-memory
 * index, a derived fact's one dependent or fired binding), and an array for it was one more object to make and one
 * more cache line to read each time the fact is joined or fired.
 *
 * <p>For the engine's per-fact records ({@link FactView.Fact}): each fact kept up to three {@link ArrayList}s of one
 * or two elements (its activations, fired bindings, dependents), three quarters of a million wrappers at
 * N = 100,000 in {@code bench inference}. Not thread-safe: owned by the engine thread.
 */
final class Bag {
    /** The most elements kept in an array; one more turns the bag into a set. */
    static final int SMALL = 8;

    private Bag() {
    }

    /** {@code bag} with {@code x} added at the end; no check for an equal element (a set form ignores one). */
    static Object add(Object bag, Object x) {
        assert !(x instanceof Object[] || x instanceof Collection) : "a bag's element is never an array or collection";
        if (bag == null) {
            return x;
        }
        if (bag instanceof Object[] a) {
            int n = count(a);
            if (n < a.length) {
                a[n] = x;
                return a;
            }
            if (n < SMALL) {
                Object[] grown = Arrays.copyOf(a, Math.min(SMALL, 2 * n));
                grown[n] = x;
                return grown;
            }
            LinkedHashSet<Object> set = new LinkedHashSet<>(Arrays.asList(a));
            set.add(x);
            return set;
        }
        if (bag instanceof Collection<?>) {
            set(bag).add(x);
            return bag;
        }
        return new Object[] {bag, x}; // the one element, and now a second
    }

    /** As {@link #add}, unless an equal element is there already. */
    static Object addIfAbsent(Object bag, Object x) {
        return contains(bag, x) ? bag : add(bag, x);
    }

    static boolean contains(Object bag, Object x) {
        if (bag == null) {
            return false;
        }
        if (bag instanceof Object[] a) {
            for (Object e : a) {
                if (e == null) {
                    return false;
                }
                if (same(e, x)) {
                    return true;
                }
            }
            return false;
        }
        if (bag instanceof Collection<?>) {
            return set(bag).contains(x);
        }
        return same(bag, x);
    }

    /** {@code bag} without the first element equal to {@code x}; null once it is empty. */
    static Object remove(Object bag, Object x) {
        if (bag == null) {
            return null;
        }
        if (bag instanceof Object[] a) {
            int n = count(a);
            for (int i = 0; i < n; i++) {
                if (same(a[i], x)) {
                    if (n == 1) {
                        return null;
                    }
                    System.arraycopy(a, i + 1, a, i, n - i - 1);
                    a[n - 1] = null;
                    return a;
                }
            }
            return a;
        }
        if (!(bag instanceof Collection<?>)) {
            return same(bag, x) ? null : bag;
        }
        Collection<Object> s = set(bag);
        s.remove(x);
        return s.isEmpty() ? null : s;
    }

    static int size(Object bag) {
        if (bag == null) {
            return 0;
        }
        if (bag instanceof Object[] a) {
            return count(a);
        }
        return bag instanceof Collection<?> ? set(bag).size() : 1;
    }

    /** The elements in insertion order (a copy: the bag may change while the caller goes through it). */
    @SuppressWarnings("unchecked")
    static <T> List<T> toList(Object bag) {
        if (bag == null) {
            return List.of();
        }
        if (bag instanceof Object[] a) {
            List<T> out = new ArrayList<>(count(a));
            for (Object e : a) {
                if (e == null) {
                    break;
                }
                out.add((T) e);
            }
            return out;
        }
        if (!(bag instanceof Collection<?>)) {
            return List.of((T) bag);
        }
        return new ArrayList<>((Collection<T>) set(bag));
    }

    /** Whether element {@code e} is {@code x}: the same object, or an equal one. */
    private static boolean same(Object e, Object x) {
        return e == x || e.equals(x);
    }

    private static int count(Object[] a) {
        int n = a.length;
        while (n > 0 && a[n - 1] == null) {
            n--;
        }
        return n;
    }

    @SuppressWarnings("unchecked")
    private static Collection<Object> set(Object bag) {
        return (Collection<Object>) bag;
    }
}
