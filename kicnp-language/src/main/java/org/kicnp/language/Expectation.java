package org.kicnp.language;

/**
 * What the dialogue expects next, so that a bare word can be read: "Ken" is a name after "What is your name?",
 * "lemonade" is a drink after "What do you want to drink?". Without an expectation a lone unknown word is not
 * understood.
 */
public enum Expectation {
    /** Nothing in particular. */
    NONE,
    /** Robovie has just asked for the user's name. */
    NAME,
    /** Robovie has just asked what the user wants to drink. */
    DRINK
}
