package org.kicnp.core;

/** Small fixtures shared by the core tests: the paper's Figure 1 hierarchy in a few lines. */
final class Frames {
    private Frames() {
    }

    static Frame cls(String name, String parent) {
        return Frame.classFrame(name).parent(parent).build();
    }

    static Frame root(String name) {
        return Frame.classFrame(name).build();
    }

    static Slot str(String name, String value) {
        return Slot.ofValue(name, DataType.STRING, Value.of(value));
    }

    static Slot instanceSlot(String name, String argument) {
        return Slot.builder(name, DataType.INSTANCE).argument(argument).required(true).build();
    }

    /** System, User, KnownUser, NewUser, HumanRobotInteraction, Speech, Mouth. */
    static KnowledgeBase figure1() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.apply(java.util.List.of(
                new Change.Add(root("System")),
                new Change.Add(Frame.classFrame("User").parent("System")
                        .slot(Slot.builder("name", DataType.STRING).defaultValue(Value.of("stranger")).build())
                        .build()),
                new Change.Add(cls("KnownUser", "User")),
                new Change.Add(cls("NewUser", "User")),
                new Change.Add(cls("HumanRobotInteraction", "System")),
                new Change.Add(cls("Speech", "HumanRobotInteraction")),
                new Change.Add(cls("Mouth", "HumanRobotInteraction"))));
        return kb;
    }
}
