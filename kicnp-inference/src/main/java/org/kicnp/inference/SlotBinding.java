package org.kicnp.inference;

import java.util.AbstractMap;
import java.util.AbstractSet;
import java.util.Iterator;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.Set;
import java.util.function.BiConsumer;

/**
 * A read-only map slot → instance over a rule's slots held by position: {@link #slotAt}, and {@link #factAt} (null
 * where the position is unbound). A rule has a handful of instance slots, so a linear search beats hashing, and a
 * binding is one small object instead of a hash table. The two kinds: the binding being built by a join
 * ({@link JoinBinding}) and a firing's finished one ({@link Binding}).
 */
abstract sealed class SlotBinding extends AbstractMap<String, String> permits Binding, JoinBinding {

    /** The number of positions. */
    abstract int width();

    abstract String slotAt(int position);

    /** The instance bound at a position; null where none is. */
    abstract String factAt(int position);

    @Override public String get(Object slot) {
        for (int i = 0, n = width(); i < n; i++) {
            String s = slotAt(i);
            if (s == slot || s.equals(slot)) {
                return factAt(i);
            }
        }
        return null;
    }

    @Override public boolean containsKey(Object slot) {
        return get(slot) != null;
    }

    @Override public boolean containsValue(Object fact) {
        for (int i = 0, n = width(); i < n; i++) {
            String f = factAt(i);
            if (f != null && f.equals(fact)) {
                return true;
            }
        }
        return false;
    }

    @Override public int size() {
        int bound = 0;
        for (int i = 0, n = width(); i < n; i++) {
            if (factAt(i) != null) {
                bound++;
            }
        }
        return bound;
    }

    @Override public void forEach(BiConsumer<? super String, ? super String> action) {
        for (int i = 0, n = width(); i < n; i++) {
            String f = factAt(i);
            if (f != null) {
                action.accept(slotAt(i), f);
            }
        }
    }

    @Override public Set<Map.Entry<String, String>> entrySet() {
        return new AbstractSet<>() {
            @Override public Iterator<Map.Entry<String, String>> iterator() {
                return new Iterator<>() {
                    private int next = skip(0);

                    private int skip(int i) {
                        while (i < width() && factAt(i) == null) {
                            i++;
                        }
                        return i;
                    }

                    @Override public boolean hasNext() {
                        return next < width();
                    }

                    @Override public Map.Entry<String, String> next() {
                        if (next >= width()) {
                            throw new NoSuchElementException();
                        }
                        int i = next;
                        next = skip(i + 1);
                        return new SimpleImmutableEntry<>(slotAt(i), factAt(i));
                    }
                };
            }

            @Override public int size() {
                return SlotBinding.this.size();
            }
        };
    }
}
