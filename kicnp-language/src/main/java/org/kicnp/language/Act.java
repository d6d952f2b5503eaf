package org.kicnp.language;

import java.util.EnumSet;
import java.util.Set;

/**
 * What an utterance does, each with the knowledge-base class its instances belong to and the cases it may carry.
 * The class names start with {@code Said} so they never clash with behaviour frames such as the scenario's
 * {@code Greeting}.
 */
public enum Act {
    /** "My name is Ken", "I'm Ken", "Call me Ken". */
    NAME_STATEMENT("SaidName", EnumSet.of(Case.ATTRIBUTE, Case.RECIPIENT)),
    /** "Tea, please", "I'd like a coffee", "Could you bring me some tea?". */
    DRINK_REQUEST("SaidDrinkRequest", EnumSet.of(Case.ACTION, Case.AGENT, Case.OBJECT, Case.RECIPIENT, Case.GOAL,
            Case.SOURCE, Case.QUANTITY, Case.TIME)),
    /** "AIBO, sit down", "Scout, go to the door", "PINO, shake hands with Ken". */
    ROBOT_COMMAND("SaidCommand", EnumSet.complementOf(EnumSet.of(Case.ATTRIBUTE, Case.POLARITY))),
    /** "Yes", "No thanks". */
    YES_NO_ANSWER("SaidYesNo", EnumSet.of(Case.POLARITY, Case.RECIPIENT)),
    /** "Hello", "Good morning, Robovie", "Goodbye", "Thank you". */
    GREETING("SaidHello", EnumSet.of(Case.ACTION, Case.RECIPIENT));

    private final String className;
    private final Set<Case> cases;

    Act(String className, Set<Case> cases) {
        this.className = className;
        this.cases = Set.copyOf(cases);
    }

    /** The class frame of this act's instances, a subclass of {@code Utterance}. */
    public String className() {
        return className;
    }

    /** The cases a frame of this act may carry. */
    public Set<Case> cases() {
        return cases;
    }

    /**
     * The slot a case goes to in this act's frames. Mostly the case's own name in camel case; the few that read
     * better in a behaviour frame are renamed: the name given, the drink asked for, the robot that is to act, and
     * the answer.
     */
    public String slotFor(Case c) {
        return switch (c) {
            case ATTRIBUTE -> "name";
            case POLARITY -> "answer";
            case AGENT -> "robot";
            case CO_AGENT -> "coAgent";
            case OBJECT -> this == DRINK_REQUEST ? "drink" : "object";
            default -> c.name().toLowerCase(java.util.Locale.ROOT);
        };
    }
}
