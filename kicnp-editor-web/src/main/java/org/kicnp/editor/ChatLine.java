package org.kicnp.editor;

import static java.util.Objects.requireNonNull;

import java.time.Instant;

/**
 * One line of the conversation the World panel shows: who spoke and what, or what the parser made of it.
 *
 * @param speaker the person or robot the line belongs to ({@code "User A"}, {@code "Robovie"}); for verdicts, the
 *     person whose words were judged
 * @param kind what sort of line it is
 * @param text the words said, or for verdicts the parser's summary ({@code "request: bring tea to Ken"}) or its
 *     reason and reply ({@code "'sit' takes no goal …"})
 */
public record ChatLine(Instant at, String speaker, Kind kind, String text) {
    /** The sorts of chat lines. */
    public enum Kind {
        /** A person's words (the editor adds these itself when someone types in the chat box). */
        USER,
        /** The parser understood the person's words. */
        UNDERSTOOD,
        /** The parser did not understand: the person is asked to say it again. */
        NOT_UNDERSTOOD,
        /** A robot's utterance. */
        ROBOT,
        /** A note from the platform (a robot disconnected, …). */
        SYSTEM
    }

    public ChatLine {
        requireNonNull(at, "at");
        requireNonNull(speaker, "speaker");
        requireNonNull(kind, "kind");
        requireNonNull(text, "text");
    }
}
