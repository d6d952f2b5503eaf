package org.kicnp.language;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.io.InputStream;
import java.util.Objects;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Value;
import org.kicnp.core.xml.KnowledgeLoader;
import org.kicnp.core.xml.SourcedFrame;

class LanguageFramesTest {
    private final SentenceParser parser = SentenceParser.standard();

    private static String xml() throws IOException {
        try (InputStream in = Objects.requireNonNull(LanguageFrames.class.getResourceAsStream(LanguageFrames.RESOURCE))) {
            return new String(in.readAllBytes(), UTF_8);
        }
    }

    @Test
    void xmlResource_holdsExactlyTheClassFrames() throws IOException {
        var fromXml = KnowledgeLoader.parseText(xml(), "language.xml", KnowledgeBase.create()).stream()
                .map(SourcedFrame::frame).toList();
        assertThat(fromXml).containsExactlyElementsOf(LanguageFrames.classes());
    }

    @Test
    void classes_haveOneSubclassOfUtterancePerAct_plusUnknown() {
        assertThat(LanguageFrames.classes()).extracting(Frame::name).containsExactly("Utterance", "SaidName",
                "SaidDrinkRequest", "SaidCommand", "SaidYesNo", "SaidHello", "SaidUnknown");
    }

    @Test
    void toFrame_ofDrinkRequest_isARuntimeInstanceTheKnowledgeBaseAccepts() {
        KnowledgeBase kb = KnowledgeBase.create();
        LanguageFrames.classes().forEach(kb::add);
        CaseFrame said = ((ParseResult.Parsed) parser.parse("I'd like a lemonade")).frame();
        Frame f = CaseFrames.toFrame(said, "said-alice-1", "alice");
        kb.add(f);
        assertThat(f.provenance()).isEqualTo(Provenance.RUNTIME);
        assertThat(kb.isA("said-alice-1", "Utterance")).isTrue();
        assertThat(kb.value("said-alice-1", "drink")).contains(Value.of("lemonade"));
        assertThat(kb.value("said-alice-1", "known")).contains(Value.of("false"));
        assertThat(kb.value("said-alice-1", "speaker")).contains(Value.of("alice"));
        assertThat(kb.value("said-alice-1", "correction")).contains(Value.of("false"));
    }

    @Test
    void toFrame_ofCommand_putsTheRobotAndActionInSlots() {
        CaseFrame said = ((ParseResult.Parsed) parser.parse("Scout, bring tea to Ken")).frame();
        Frame f = CaseFrames.toFrame(said, "said-1");
        assertThat(f.parent()).contains("SaidCommand");
        assertThat(f.ownSlot("robot").flatMap(s -> s.value())).contains(Value.of("Scout"));
        assertThat(f.ownSlot("action").flatMap(s -> s.value())).contains(Value.of("bring"));
        assertThat(f.ownSlot("object").flatMap(s -> s.value())).contains(Value.of("tea"));
        assertThat(f.ownSlot("recipient").flatMap(s -> s.value())).contains(Value.of("Ken"));
        assertThat(f.ownSlot("speaker")).isEmpty();
    }

    @Test
    void everyActsFrame_fitsItsClass_inAKnowledgeBase() {
        KnowledgeBase kb = KnowledgeBase.create();
        LanguageFrames.classes().forEach(kb::add);
        String[] sentences = {"My name is Ken", "No, coffee please", "PINO, shake hands with Ken", "no thanks",
            "Hello, Robovie"};
        for (int i = 0; i < sentences.length; i++) {
            CaseFrame said = ((ParseResult.Parsed) parser.parse(sentences[i])).frame();
            kb.add(CaseFrames.toFrame(said, "s" + i, "alice"));
        }
        assertThat(kb.value("s0", "name")).contains(Value.of("Ken"));
        assertThat(kb.value("s1", "correction")).contains(Value.of("true"));
        assertThat(kb.value("s2", "coAgent")).contains(Value.of("Ken"));
        assertThat(kb.value("s3", "answer")).contains(Value.of("no"));
        assertThat(kb.value("s4", "recipient")).contains(Value.of("Robovie"));
    }

    @Test
    void caseFrame_withACaseItsActCannotCarry_isRefusedWithMessage() {
        assertThatThrownBy(() -> new CaseFrame(Act.GREETING, java.util.Map.of(Case.OBJECT,
                Filler.known("tea", SemanticClass.DRINK, "tea")), false, "hello tea"))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("A case frame of act 'GREETING' has no case 'OBJECT'.");
    }

    @Test
    void parse_isFast_wellUnderAMillisecondPerSentence() {
        String[] sentences = {"Could you bring me some tea?", "Scout, bring the cup from the kitchen to the table",
            "They call me Ken Smith", "blorf zap", "No, coffee please"};
        for (int i = 0; i < 10_000; i++) {
            parser.parse(sentences[i % sentences.length]);
        }
        int n = 20_000;
        long start = System.nanoTime();
        for (int i = 0; i < n; i++) {
            parser.parse(sentences[i % sentences.length]);
        }
        double micros = (System.nanoTime() - start) / 1000.0 / n;
        assertThat(micros).as("microseconds per sentence").isLessThan(200.0);
    }
}
