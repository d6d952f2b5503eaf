package org.kicnp.cli.platform;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.inference.EngineOptions;
import org.kicnp.inference.InferenceEngine;

class EngineLinkTest {

    @Test
    void prove_tooBroadForTheEnginesLimit_failsWithTheLimitsSentence_andANarrowerOneIsAnswered() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("User").build());
        kb.add(Frame.classFrame("Mouth").build());
        kb.add(Frame.classFrame("Talk")
                .slot(Slot.builder("mUser", DataType.INSTANCE).argument("User").required(true).build())
                .slot(Slot.builder("mMouth", DataType.INSTANCE).argument("Mouth").required(true).build()).build());
        for (int i = 0; i < 5; i++) {
            kb.add(Frame.instance("u" + i, "User").provenance(Provenance.RUNTIME).build());
            kb.add(Frame.instance("m" + i, "Mouth").provenance(Provenance.RUNTIME).build());
        }
        try (InferenceEngine engine = InferenceEngine.builder(kb)
                .options(EngineOptions.defaults().withMaxQuestionSteps(10)).build()) {
            EngineLink link = new EngineLink(kb, Runnable::run);
            link.attach(engine);

            assertThat(link.prove("Talk", Map.of())).failsWithin(java.time.Duration.ofSeconds(10))
                    .withThrowableOfType(java.util.concurrent.ExecutionException.class)
                    .havingCause().isInstanceOf(IllegalArgumentException.class)
                    .withMessage("The question about 'Talk' is too broad: it tried 10 combinations of instances without "
                            + "finishing (the engine's maxQuestionSteps); hold some of the slots fixed to narrow it.");
            assertThat(link.prove("Talk", Map.of("mUser", "u1")).join()).as("narrowed: 5 combinations").hasSize(5);
        }
    }
}
