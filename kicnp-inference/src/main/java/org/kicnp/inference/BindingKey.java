package org.kicnp.inference;

import java.util.Arrays;
import java.util.Objects;

/**
 * The identity of a binding for refraction and the agenda: the behavior frame's name and the instances bound to its
 * required slots, in slot order. It outlives a recompiled rule (the frame name, not the {@link Rule} object, is part
 * of it), so a binding that fired before a frame was edited stays refracted after.
 *
 * <p>Every firing keeps one for as long as what it derived lives (its {@link Derivation} and the refraction lists of
 * the facts bound), so the first two instances are fields of the key itself and only a third and more take an array:
 * a behavior frame binds two instance slots most often, and a key with an array of two was 48 bytes where this is 32.
 */
final class BindingKey {
    private static final String[] NONE = new String[0];

    private final String frame;
    /** The first two instances bound (null past the width). */
    private final String first;
    private final String second;
    /** The instances bound after the first two (an empty array when there are none). */
    private final String[] rest;
    /**
     * Worked out when first asked (0: not yet), as {@link String#hashCode} is: a key is compared with a few others
     * in a fact's short lists far more often than it is hashed, and hashing it reads every character of names the
     * engine made a moment ago, most of which nothing else hashes.
     */
    private int hash;

    /** The key of {@code frame} binding {@code facts} in slot order (copied: the caller may reuse the array). */
    BindingKey(String frame, String[] facts) {
        this.frame = Objects.requireNonNull(frame, "frame");
        int n = facts.length;
        this.first = n > 0 ? Objects.requireNonNull(facts[0]) : null;
        this.second = n > 1 ? Objects.requireNonNull(facts[1]) : null;
        this.rest = n > 2 ? Arrays.copyOfRange(facts, 2, n) : NONE;
    }

    /** The behavior frame. */
    String frame() {
        return frame;
    }

    /** The number of instances bound. */
    int width() {
        return second != null ? 2 + rest.length : first != null ? 1 : 0;
    }

    /** The instance bound at {@code position} (0 to {@link #width()} - 1). */
    String fact(int position) {
        return switch (position) {
            case 0 -> Objects.requireNonNull(first, "no instance at 0");
            case 1 -> Objects.requireNonNull(second, "no instance at 1");
            default -> rest[position - 2];
        };
    }

    /** The bound instances, in slot order: a new array. */
    String[] facts() {
        String[] out = new String[width()];
        for (int i = 0; i < out.length; i++) {
            out[i] = fact(i);
        }
        return out;
    }

    @Override public boolean equals(Object o) {
        return o instanceof BindingKey k && (k.hash == 0 || hash == 0 || k.hash == hash) && k.frame.equals(frame)
                && Objects.equals(k.first, first) && Objects.equals(k.second, second) && Arrays.equals(k.rest, rest);
    }

    @Override public int hashCode() {
        int h = hash;
        if (h == 0) {
            int facts = 1; // Arrays.hashCode of the instances, as when they were an array: a key's hash is unchanged
            for (int i = 0, n = width(); i < n; i++) {
                facts = 31 * facts + fact(i).hashCode();
            }
            h = 31 * frame.hashCode() + facts;
            hash = h; // a benign race, as String's: every thread works out the same value
        }
        return h;
    }

    @Override public String toString() {
        return frame + Arrays.toString(facts());
    }
}
