package org.kicnp.core;

/**
 * Where a frame came from, which decides whether it is kept on disk.
 * Declared and learned frames are durable; runtime frames (stimuli, derived instances) live in memory only.
 */
public enum Provenance {
    /** Written by a person: loaded from XML or made in the editor. */
    DECLARED,
    /** Learned by the system at run time, such as a new user's name; durable and marked in the editor. */
    LEARNED,
    /** Asserted or derived while the platform runs; never written to the store. */
    RUNTIME;

    /** Whether frames of this provenance survive a restart. */
    public boolean durable() {
        return this != RUNTIME;
    }
}
