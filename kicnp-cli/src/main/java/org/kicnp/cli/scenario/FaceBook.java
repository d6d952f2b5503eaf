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
 * the descriptor as comma-separated numbers, or whose {@code face} slot holds it as a list. A person is enrolled
 * under the name of their frame, not under what they are called, so that two people called Ken stay two people:
 * the recogniser reports the frame (FaceDetection creates an instance of it) and the frame's {@code name} slot says
 * what to call them. A sighting (an instance of a learned class, as FaceDetection creates) adds its face to its
 * class's person. Enrols them when attached (so a restarted server still knows its users) and on every change.
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
            switch (e) {
                case FrameEvent.Added a -> enrol(a.frame());
                case FrameEvent.Replaced r -> {
                    if (isPerson(r.frame())) {
                        recognizer.forget(r.frame().name()); // the face it had is no longer theirs
                    }
                    enrol(r.frame());
                }
                case FrameEvent.Removed r -> {
                    if (isPerson(r.frame())) {
                        recognizer.forget(r.frame().name());
                    }
                }
            }
        }
    }

    private void enrol(Frame f) {
        if (f.name().equals(FaceMemory.KNOWN_USER) || !kb.contains(f.name()) || !kb.isA(f.name(), FaceMemory.KNOWN_USER)) {
            return;
        }
        Optional<FaceVector> face = FaceMemory.face(f).or(() -> faceText(f));
        face.ifPresent(v -> recognizer.enroll(isPerson(f) ? f.name() : f.parent().orElseThrow(), v));
    }

    /** A person's own frame (a class, or an instance of KnownUser itself), not a sighting of a learned class. */
    private static boolean isPerson(Frame f) {
        return f.isClass() || f.parent().map(FaceMemory.KNOWN_USER::equals).orElse(true);
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
