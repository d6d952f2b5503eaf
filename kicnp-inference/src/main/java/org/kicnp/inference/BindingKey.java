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
    private final int hash;

    BindingKey(String frame, String[] facts) {
        this.frame = frame;
        this.facts = facts;
        this.hash = 31 * frame.hashCode() + Arrays.hashCode(facts);
    }

    /** The bound instances, in slot order; not to be changed. */
    String[] facts() {
        return facts;
    }

    @Override public boolean equals(Object o) {
        return o instanceof BindingKey k && k.hash == hash && k.frame.equals(frame) && Arrays.equals(k.facts, facts);
    }

    @Override public int hashCode() {
        return hash;
    }

    @Override public String toString() {
        return frame + Arrays.toString(facts);
    }
}
