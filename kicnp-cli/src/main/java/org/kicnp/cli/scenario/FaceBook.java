package org.kicnp.cli.scenario;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameEvent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeListener;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.kicnp.robots.FaceMemory;
import org.kicnp.robots.FaceRecognizer;
import org.kicnp.robots.FaceVector;

/**
 * Keeps Robovie's face recogniser in step with the faces the knowledge base has learned: every frame below
 * {@code KnownUser} (the learned sub-frames GotNewName registers, or instances) whose {@code faceText} slot holds
 * the descriptor as comma-separated numbers, or whose {@code face} slot holds it as a list. Enrols them when
 * attached (so a restarted server still knows its users) and on every change.
 */
public final class FaceBook implements KnowledgeListener {
    private final KnowledgeBase kb;
    private final FaceRecognizer recognizer;

    private FaceBook(KnowledgeBase kb, FaceRecognizer recognizer) {
        this.kb = kb;
        this.recognizer = recognizer;
    }

    public static FaceBook attach(KnowledgeBase kb, FaceRecognizer recognizer) {
        FaceBook book = new FaceBook(kb, recognizer);
        kb.addListener(book);
        for (Frame f : kb.frames()) {
            book.enrol(f);
        }
        return book;
    }

    public void detach() {
        kb.removeListener(this);
    }

    @Override public void changed(ChangeSet changes) {
        for (FrameEvent e : changes.events()) {
            if (!(e instanceof FrameEvent.Removed)) {
                enrol(e.frame());
            }
        }
    }

    private void enrol(Frame f) {
        if (f.name().equals(FaceMemory.KNOWN_USER) || !kb.contains(f.name()) || !kb.isA(f.name(), FaceMemory.KNOWN_USER)) {
            return;
        }
        Optional<FaceVector> face = FaceMemory.face(f).or(() -> faceText(f));
        face.ifPresent(v -> recognizer.enroll(FaceMemory.personName(f), v));
    }

    static Optional<FaceVector> faceText(Frame f) {
        return f.ownSlot("faceText").flatMap(Slot::value).map(Value::text).filter(t -> !t.isBlank()).flatMap(t -> {
            List<Double> values = new ArrayList<>();
            try {
                for (String part : t.split(",")) {
                    values.add(Double.parseDouble(part.strip()));
                }
            } catch (NumberFormatException e) {
                return Optional.empty();
            }
            return Optional.of(FaceVector.of(values));
        });
    }
}
