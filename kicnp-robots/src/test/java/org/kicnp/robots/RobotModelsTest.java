package org.kicnp.robots;

import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;
import org.kicnp.protocol.FrameText;

import java.util.Map;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

/** The capability frames of the four robots and the conversion of text arguments. */
class RobotModelsTest {

    @Test
    void capabilityFrames_ofAllFourRobots_areAcceptedTogetherByAKnowledgeBase() {
        KnowledgeBase kb = KnowledgeBase.create();
        for (RobotModel m : RobotModels.all()) {
            m.capabilityFrames().forEach(kb::put);
        }

        assertThat(kb.children(ActionSpec.ROOT)).extracting(Frame::name)
                .contains("ScoutGoTo", "RobovieSay", "PinoShakeHands", "AiboLieDown", "AiboSetLights");
        assertThat(kb.value("RobovieSay", "command")).contains(Value.of("say"));
        assertThat(kb.slot("ScoutGoTo", "x").orElseThrow().slot().required()).isTrue();
    }

    @Test
    void capabilityFrame_survivesTheXmlTheAgentSends() {
        Frame frame = RobotModels.aibo().action("set_lights").orElseThrow().toFrame("aibo");
        KnowledgeBase context = KnowledgeBase.create();
        context.put(ActionSpec.rootFrame());

        assertThat(FrameText.parse(FrameText.toXml(frame), "test", context)).containsExactly(frame);
    }

    @Test
    void toArgs_convertsTextToTheArgumentTypes() {
        ActionSpec goTo = RobotModels.scout().action("ScoutGoTo").orElseThrow();
        ActionSpec lights = RobotModels.aibo().action("AiboSetLights").orElseThrow();

        assertThat(goTo.toArgs(Map.of("x", "6.2", "y", " 3 "))).isEqualTo(Map.of("x", 6.2, "y", 3.0));
        assertThat(lights.toArgs(Map.of("lights", "red, off"))).isEqualTo(Map.of("lights", java.util.List.of("red", "off")));
    }

    @Test
    void toArgs_refusesUnknownAndMissingArguments() {
        ActionSpec goTo = RobotModels.scout().action("go_to").orElseThrow();

        assertThatThrownBy(() -> goTo.toArgs(Map.of("x", "1", "y", "1", "speed", "2")))
                .hasMessage("Action ScoutGoTo has no argument 'speed'; it takes [x, y, heading_deg, tolerance_m, stall_s].");
        assertThatThrownBy(() -> goTo.toArgs(Map.of("x", "1")))
                .hasMessage("Action ScoutGoTo needs the argument 'y'.");
        assertThatThrownBy(() -> goTo.toArgs(Map.of("x", "NaN", "y", "1")))
                .hasMessage("Argument 'x' of ScoutGoTo must be a number, not 'NaN'.");
    }
}
