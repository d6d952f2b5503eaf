package org.kicnp.language;

/** The semantic class of a filler, as the lexicon knows it; case-marker rules and valency checks look at it. */
public enum SemanticClass {
    /** Something to drink: tea, coffee, water, juice (or an unknown noun asked for as a drink). */
    DRINK,
    /** One of the robots: Robovie, PINO, Scout, AIBO (or "you", the robot spoken to). */
    ROBOT,
    /** A place in the room: the door, the table, the kitchen; or a direction such as here or left. */
    PLACE,
    /** A person: me (the speaker), Ken, the user. */
    PERSON,
    /** A proper name given by the speaker. */
    NAME,
    /** Any other thing: a ball, a cup, or an unknown noun. */
    THING,
    /** A predicate. */
    ACTION,
    /** An amount. */
    QUANTITY,
    /** A point in time. */
    TIME,
    /** A yes/no value. */
    ANSWER
}
