package org.kicnp.inference;

import java.util.Arrays;

/**
 * The identity of a binding for refraction and the agenda: the behavior frame's name and the instances bound to its
 * required slots, in slot order. It outlives a recompiled rule (the frame name, not the {@link Rule} object, is part
 * of it), so a binding that fired before a frame was edited stays refracted after.
 */
final class BindingKey {
    private final String frame;
    private final String[] facts;
    /**
     * Worked out when first asked (0: not yet), as {@link String#hashCode} is: a key is compared with a few others
     * in a fact's short lists far more often than it is hashed, and hashing it reads every character of names the
     * engine made a moment ago, most of which nothing else hashes.
     */
    private int hash;

    BindingKey(String frame, String[] facts) {
        this.frame = frame;
        this.facts = facts;
    }

    /** The behavior frame. */
    String frame() {
        return frame;
    }

    /** The bound instances, in slot order; not to be changed. */
    String[] facts() {
        return facts;
    }

    @Override public boolean equals(Object o) {
        return o instanceof BindingKey k && (k.hash == 0 || hash == 0 || k.hash == hash) && k.frame.equals(frame)
                && Arrays.equals(k.facts, facts);
    }

    @Override public int hashCode() {
        int h = hash;
        if (h == 0) {
            h = 31 * frame.hashCode() + Arrays.hashCode(facts);
            hash = h; // a benign race, as String's: every thread works out the same value
        }
        return h;
    }

    @Override public String toString() {
        return frame + Arrays.toString(facts);
    }
}
