package org.kicnp.editor;

import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Relation;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/** A small knowledge base in the shape of the paper's figure 1 and tables 3 and 4, for the editor's tests. */
final class SampleKnowledge {
    private SampleKnowledge() {
    }

    static KnowledgeBase create() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("System").build());
        kb.add(Frame.classFrame("Robot").parent("System")
                .slot(Slot.builder("robotName", DataType.STRING).role("display name").build())
                .slot(Slot.builder("battery", DataType.INTEGER).defaultValue(Value.of(100)).build())
                .build());
        kb.add(Frame.classFrame("HumanoidRobot").parent("Robot").build());
        kb.add(Frame.instance("Robovie", "HumanoidRobot")
                .slot(Slot.ofValue("robotName", DataType.STRING, Value.of("Robovie"))).build());
        kb.add(Frame.classFrame("User").parent("System").build());
        kb.add(Frame.classFrame("KnownUser").parent("User").build());
        kb.add(Frame.classFrame("NewUser").parent("User").build());
        kb.add(Frame.classFrame("Taro").parent("KnownUser").provenance(Provenance.LEARNED).build());
        kb.add(Frame.classFrame("Mouth").parent("System").build());
        kb.add(Frame.classFrame("Behavior").parent("System").build());
        kb.add(Frame.classFrame("Speech").parent("Behavior")
                .slot(Slot.builder("mfunction", DataType.STRING).value(Value.of("sendmsg")).unique(true).build())
                .build());
        kb.add(Frame.classFrame("AskUserName").parent("Speech")
                .slot(Slot.builder("mUser", DataType.INSTANCE).argument("NewUser").required(true).unique(true).build())
                .slot(Slot.builder("mMouth", DataType.INSTANCE).argument("Mouth").required(true).unique(true).build())
                .slot(Slot.builder("onInstantiate", DataType.STRING)
                        .value(Value.of("sendmsg(s.mMouth, \"What is your name?\");")).build())
                .build());
        kb.add(Frame.classFrame("Greeting").parent("Speech")
                .linkTo(Relation.Coordination.SUCCESSION, "AskUserName")
                .slot(Slot.builder("mUser", DataType.INSTANCE).argument("KnownUser").required(true).build())
                .build());
        return kb;
    }
}
