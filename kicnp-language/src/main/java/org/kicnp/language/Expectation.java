package org.kicnp.language;

import static java.util.Objects.requireNonNull;

import java.util.Locale;

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
    DRINK;

    /**
     * What a robot's line leaves the dialogue expecting: a question ("...?") that mentions a name expects a name, one
     * that mentions a drink a drink, anything else nothing. Whoever relays a person's words (the terminal demo's
     * microphone, the editor's chat) keeps the expectation of the robot's last line and passes it with
     * {@link ParserAgent#subject(Expectation)}.
     */
    public static Expectation after(String robotLine) {
        String q = requireNonNull(robotLine, "robotLine").strip().toLowerCase(Locale.ROOT);
        if (!q.endsWith("?")) {
            return NONE;
        }
        return q.contains("name") ? NAME : q.contains("drink") ? DRINK : NONE;
    }
}
