package org.kicnp.inference;

import static org.kicnp.inference.InferenceEngine.FEEDBACK_CLASS;

import java.util.List;
import java.util.Locale;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The {@value InferenceEngine#FEEDBACK_CLASS} frames through which finished actions come back into the knowledge
 * base: the class frame, and a runtime instance per finished action, so behavior frames can match on feedback. Kept
 * apart from {@link ActionCoordinator}, which tracks the actions, as the one place that knows the feedback frame's
 * shape (its class frame and its instances must name the same slots).
 */
final class ActionFeedbackFrames {
    /** Logged under the engine's name: the public class is the one users configure logging for. */
    private static final Logger LOG = LoggerFactory.getLogger(InferenceEngine.class);
    private final KnowledgeBase kb;

    ActionFeedbackFrames(KnowledgeBase kb) {
        this.kb = kb;
    }

    /** Puts the feedback instance of a finished action; a refusal is logged, the action stands as it is. */
    void assertFeedback(ActionCoordinator.Tracked t) {
        Action a = t.action;
        Frame f = Frame.instance(FEEDBACK_CLASS + "-" + a.id(), FEEDBACK_CLASS).provenance(Provenance.RUNTIME)
                .slot(str("action", a.id())).slot(str("robot", a.robot())).slot(str("name", a.name()))
                .slot(str("status", t.status.name().toLowerCase(Locale.ROOT))).slot(str("result", t.detail))
                .slot(str("frame", a.frame())).slot(str("issuedBy", a.instance())).build();
        try {
            kb.put(f);
        } catch (KnowledgeException e) {
            LOG.warn("Could not record feedback for action '{}': {}", a.id(), e.getMessage());
        }
    }

    /** {@link InferenceEngine#feedbackClass()}. */
    static Frame classFrame() {
        Frame.Builder b = Frame.classFrame(FEEDBACK_CLASS);
        for (String s : List.of("action", "robot", "name", "status", "result", "frame", "issuedBy")) {
            b.slot(Slot.builder(s, DataType.STRING).build());
        }
        return b.build();
    }

    private static Slot str(String name, String value) {
        return Slot.ofValue(name, DataType.STRING, Value.of(value));
    }
}
