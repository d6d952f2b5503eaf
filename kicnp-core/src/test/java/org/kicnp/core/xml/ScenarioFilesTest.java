package org.kicnp.core.xml;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.FrameKind;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Value;

class ScenarioFilesTest {
    static final Path TABLE5 = Path.of("..", "scenarios", "table5");
    /** The paper's Table 4, as printed. */
    static final String TABLE4 = """
<FRAME>
  <NAME>Greeting</NAME>
  <ISA>Speech</ISA>
  <ISINSTANCE>FALSE</ISINSTANCE>
  <SLOTLIST>
    <SLOT>
      <NAME>mUser</NAME>
      <TYPE>TYPE_INSTANCE</TYPE>
      <CONDITION>COND_ANY</CONDITION>
      <ARGUMENT>KnownUser</ARGUMENT>
      <VALUE></VALUE>
      <REQUIRED>TRUE</REQUIRED>
      <SHARED>TRUE</SHARED>
      <UNIQUE>TRUE</UNIQUE>
    </SLOT>
    <SLOT>
      <NAME>mMouth</NAME>
      <TYPE>TYPE_INSTANCE</TYPE>
      <CONDITION>COND_ANY</CONDITION>
      <ARGUMENT>Mouth</ARGUMENT>
      <VALUE></VALUE>
      <REQUIRED>TRUE</REQUIRED>
      <SHARED>TRUE</SHARED>
      <UNIQUE>TRUE</UNIQUE>
    </SLOT>
    <SLOT>
      <NAME>onInstantiate</NAME>
      <TYPE>TYPE_STR</TYPE>
      <CONDITION>COND_ANY</CONDITION>
      <ARGUMENT></ARGUMENT>
      <VALUE>Sendmsg(s.mMouth, “Hi! Nice to meet you. Welcome to visit my room!”);</VALUE>
      <REQUIRED>FALSE</REQUIRED>
      <SHARED>TRUE</SHARED>
      <UNIQUE>TRUE</UNIQUE>
    </SLOT>
  </SLOTLIST>
</FRAME>
""";

    @Test
    void load_table5Directory_loadsEveryFileTogether() {
        KnowledgeBase kb = KnowledgeBase.create();

        List<SourcedFrame> loaded = KnowledgeLoader.load(kb, List.of(TABLE5));

        assertThat(loaded).hasSize(kb.size());
        assertThat(kb.frames()).extracting(f -> f.name()).contains("System", "Robot", "HumanoidRobot", "MobileRobot",
                "User", "KnownUser", "NewUser", "HumanRobotInteraction", "Gesture", "Speech", "Strategy",
                "OperationStrategy", "PerformingTasks", "Behaviors", "Robovie", "PINO", "Scout", "AIBO", "Mouth",
                "AskUserName", "Greeting", "FaceDetection", "FirstMeet", "GotNewName", "AIBOAction1",
                "RobovieToAIBOCommand1");
        assertThat(kb.instancesOf("MobileRobot")).extracting(f -> f.name()).containsExactly("Scout", "AIBO");
        assertThat(kb.value("PINO", "degreesOfFreedom")).contains(Value.of(26L));
        assertThat(kb.require("PINO").ownSlot("degreesOfFreedom").orElseThrow().type()).isEqualTo(DataType.INTEGER);
    }

    @Test
    void load_greetingAsPrintedInTable4_keepsTheTypographicQuotes() {
        KnowledgeBase kb = KnowledgeBase.create();

        KnowledgeLoader.load(kb, List.of(TABLE5));

        var greeting = kb.require("Greeting");
        assertThat(greeting.kind()).isEqualTo(FrameKind.CLASS);
        assertThat(greeting.parent()).contains("Speech");
        assertThat(greeting.slots()).extracting(s -> s.name()).containsExactly("mUser", "mMouth", "onInstantiate");
        assertThat(greeting.ownSlot("mUser").orElseThrow().argument()).contains("KnownUser");
        assertThat(greeting.ownSlot("mUser").orElseThrow().required()).isTrue();
        assertThat(greeting.ownSlot("onInstantiate").orElseThrow().value()).contains(
                Value.of("Sendmsg(s.mMouth, \u201CHi! Nice to meet you. Welcome to visit my room!\u201D);"));
    }

    @Test
    void greetingFile_isTable4Verbatim() throws Exception {
        assertThat(Files.readString(TABLE5.resolve("greeting.xml"))).isEqualTo(TABLE4);
    }

    @Test
    void load_askUserName_readsTable3Words() {
        KnowledgeBase kb = KnowledgeBase.create();

        KnowledgeLoader.load(kb, List.of(TABLE5));

        var ask = kb.require("AskUserName");
        assertThat(ask.ownSlot("mUser").orElseThrow().type()).isEqualTo(DataType.INSTANCE);
        assertThat(ask.ownSlot("mfunction").orElseThrow().required()).isFalse();
        assertThat(ask.ownSlot("mfunction").orElseThrow().unique()).isTrue();
        assertThat(ask.ownSlot("mfunction").orElseThrow().value()).contains(Value.of("sendmsg"));
    }
}
