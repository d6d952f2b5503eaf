package org.kicnp.language;

/**
 * The deep cases of a case frame (Fillmore 1968, as surveyed by Bruce 1975), plus the two this parser needs for
 * what is not an event: the name a speaker gives ({@link #ATTRIBUTE}) and the polarity of an answer.
 */
public enum Case {
    /** The predicate itself, normalised: {@code sit}, {@code go}, {@code bring}, {@code want}, {@code hello}. */
    ACTION,
    /** Who is to act: the robot addressed by name (the vocative), or {@code addressee} for "you". */
    AGENT,
    /** What is acted on or asked for: the tea, the door, the person to follow. */
    OBJECT,
    /** Who receives or benefits (to/for a person, an indirect object, the speaker of "I'd like"). */
    RECIPIENT,
    /** Where a movement ends or a gaze goes (to/at/into, and adverbs such as here or left). */
    GOAL,
    /** Where a movement starts (from). */
    SOURCE,
    /** With what (with + a thing). */
    INSTRUMENT,
    /** With whom (with + a person or robot): shake hands with Ken. */
    CO_AGENT,
    /** Where something happens (near, next to, on, in, by). */
    LOCATION,
    /** How much: {@code 1}, {@code 1 cup}, {@code 2 cups}, {@code some}. */
    QUANTITY,
    /** When: now, later, soon. */
    TIME,
    /** What the speaker says they are called (the essive of "I am Ken"). */
    ATTRIBUTE,
    /** The value of a yes/no answer: {@code yes} or {@code no}. */
    POLARITY
}
