package org.kicnp.cli.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.robots.FaceRecognizer;
import org.kicnp.robots.FaceVector;

/** Robovie's recogniser fed from the learned users of a knowledge base, as GotNewName registers them. */
class FaceBookTest {
    private static final FaceVector KEN = FaceVector.of(1, 0, 0, 0);
    private static final FaceVector OTHER_KEN = FaceVector.of(0, 0, 1, 0);

    private static KnowledgeBase users() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("User").root()
                .slot(Slot.builder("name", DataType.STRING).build())
                .slot(Slot.builder("faceText", DataType.STRING).build())
                .build());
        kb.add(Frame.classFrame("KnownUser").parent("User").build());
        return kb;
    }

    /** What GotNewName's learn() adds: a LEARNED class under KnownUser with text slots. */
    private static Frame learned(String frame, String name, FaceVector face) {
        String text = String.join(",", face.toList().stream().map(String::valueOf).toList());
        return Frame.classFrame(frame).parent("KnownUser").provenance(Provenance.LEARNED)
                .slot(Slot.ofValue("name", DataType.STRING, Value.of(name)))
                .slot(Slot.ofValue("faceText", DataType.STRING, Value.of(text)))
                .build();
    }

    @Test
    void twoPeopleOfOneName_areEnrolledUnderTheirOwnFrames_andEachFaceIsTheirs() {
        KnowledgeBase kb = users();
        FaceRecognizer recognizer = FaceRecognizer.create(0.3);
        FaceBook.attach(kb, recognizer);
        kb.add(learned("Ken", "Ken", KEN));
        kb.add(learned("Ken_2", "Ken", OTHER_KEN));

        assertThat(recognizer.names()).containsExactlyInAnyOrder("Ken", "Ken_2");
        assertThat(recognizer.recognize(KEN)).map(FaceRecognizer.Match::name).contains("Ken");
        assertThat(recognizer.recognize(OTHER_KEN)).map(FaceRecognizer.Match::name).contains("Ken_2");
    }

    @Test
    void aPersonRemovedOrGivenANewFace_isForgottenOrRecognisedByTheNewOneOnly() {
        KnowledgeBase kb = users();
        kb.add(learned("Ken", "Ken", KEN));
        kb.add(learned("Anna", "Anna", FaceVector.of(0, 1, 0, 0)));
        FaceRecognizer recognizer = FaceRecognizer.create(0.3);
        FaceBook.attach(kb, recognizer);

        kb.replace(learned("Ken", "Ken", OTHER_KEN));
        assertThat(recognizer.recognize(OTHER_KEN)).map(FaceRecognizer.Match::name).contains("Ken");
        assertThat(recognizer.recognize(KEN)).isEmpty();

        kb.remove("Ken");
        assertThat(recognizer.names()).containsExactly("Anna");
    }
}
