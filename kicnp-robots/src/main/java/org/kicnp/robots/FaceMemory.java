package org.kicnp.robots;

import org.kicnp.core.ChangeSet;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameEvent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeListener;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * Keeps a {@link FaceRecognizer} in step with the knowledge base: every frame below {@code KnownUser} (a sub-frame or
 * an instance, as the paper's GotNewName registers a new user) that has a {@code face} slot, a {@code TYPE_LIST} of
 * {@code TYPE_FLOAT}, is enrolled under its frame name and forgotten when removed. The frame name, not the person's
 * {@code name} slot, is what the recogniser reports: two people of one name are two frames, and stay two people.
 */
public final class FaceMemory implements KnowledgeListener {
    public static final String KNOWN_USER = "KnownUser";
    public static final String FACE_SLOT = "face";
    public static final String NAME_SLOT = "name";

    private final KnowledgeBase kb;
    private final FaceRecognizer recognizer;

    private FaceMemory(KnowledgeBase kb, FaceRecognizer recognizer) {
        this.kb = kb;
        this.recognizer = recognizer;
    }

    /** Enrols every known user's face now and follows later changes. */
    public static FaceMemory attach(KnowledgeBase kb, FaceRecognizer recognizer) {
        Objects.requireNonNull(kb, "kb");
        Objects.requireNonNull(recognizer, "recognizer");
        FaceMemory memory = new FaceMemory(kb, recognizer);
        kb.addListener(memory);
        for (Frame f : kb.frames()) {
            memory.enrol(f);
        }
        return memory;
    }

    public FaceRecognizer recognizer() {
        return recognizer;
    }

    /**
     * Learns a new user: adds (or replaces) the LEARNED instance {@code name} of {@code KnownUser} with its face,
     * which this memory then enrols. The knowledge base must know the class {@code KnownUser}.
     */
    public static Frame remember(KnowledgeBase kb, String name, FaceVector face) {
        List<Value> components = new ArrayList<>(face.dimension());
        for (double v : face.toArray()) {
            components.add(Value.of(v));
        }
        Frame user = Frame.instance(name, KNOWN_USER)
                .slot(Slot.ofValue(NAME_SLOT, DataType.STRING, Value.of(name)))
                .slot(Slot.builder(FACE_SLOT, DataType.LIST).argument(DataType.FLOAT.xmlName())
                        .value(new Value.Lst(components)).build())
                .provenance(Provenance.LEARNED)
                .build();
        kb.put(user);
        return user;
    }

    @Override public void changed(ChangeSet changes) {
        for (FrameEvent e : changes.events()) {
            switch (e) {
                case FrameEvent.Added a -> enrol(a.frame());
                case FrameEvent.Replaced r -> {
                    Frame before = r.before().orElseThrow();
                    if (face(before).isPresent()) {
                        recognizer.forget(before.name());
                    }
                    enrol(r.frame());
                }
                case FrameEvent.Removed r -> {
                    if (face(r.frame()).isPresent()) {
                        recognizer.forget(r.frame().name());
                    }
                }
            }
        }
    }

    private void enrol(Frame f) {
        if (f.name().equals(KNOWN_USER) || !kb.contains(f.name()) || !kb.isA(f.name(), KNOWN_USER)) {
            return;
        }
        face(f).ifPresent(face -> recognizer.enroll(f.name(), face));
    }

    /** The person a KnownUser frame stands for: its {@code name} slot, else the frame's name. */
    public static String personName(Frame f) {
        return f.ownSlot(NAME_SLOT).flatMap(Slot::value)
                .filter(v -> v instanceof Value.Str).map(Value::text).orElse(f.name());
    }

    /** The frame's own {@code face} slot as a vector, if it holds a non-empty list of numbers. */
    public static Optional<FaceVector> face(Frame f) {
        return f.ownSlot(FACE_SLOT).flatMap(Slot::value).flatMap(v -> {
            if (!(v instanceof Value.Lst list) || list.items().isEmpty()) {
                return Optional.empty();
            }
            double[] out = new double[list.items().size()];
            for (int i = 0; i < out.length; i++) {
                switch (list.items().get(i)) {
                    case Value.Real r -> out[i] = r.value();
                    case Value.Int n -> out[i] = n.value();
                    case Value.Str text -> { // a list read without its element type (no ARGUMENT) holds text
                        try {
                            out[i] = Double.parseDouble(text.value().strip());
                        } catch (NumberFormatException e) {
                            return Optional.empty();
                        }
                    }
                    default -> {
                        return Optional.empty();
                    }
                }
            }
            return Optional.of(FaceVector.of(out));
        });
    }
}
