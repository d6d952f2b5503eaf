package org.kicnp.robots;

import org.kicnp.agent.AgentException;
import org.kicnp.agent.AgentOptions;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.protocol.ChangeKind;
import org.kicnp.protocol.FrameText;
import org.kicnp.protocol.Message;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The agent of the simulated Robovie, who leads the interaction: besides its actions it recognises the faces its
 * eye cameras see. The faces it knows are those of the {@code KnownUser} frames in the platform's knowledge base
 * (their {@code face} slot): read when it connects and followed by subscription, so a user the platform learns
 * (GotNewName) is greeted by name on the next visit. Each {@code face_seen} signal carries the known user's frame
 * (its name; the frame's {@code name} slot says what the person is called) or {@code unknown}, and the descriptor, for
 * the platform's frames to act on.
 */
public final class RobovieAgent extends RobotAgent {
    private static final Logger LOG = LoggerFactory.getLogger(RobovieAgent.class);

    private final FaceRecognizer faces;
    /** The known users whose face is enrolled (by frame name). */
    private final Set<String> enrolled = ConcurrentHashMap.newKeySet();
    private volatile boolean subscribed;

    public RobovieAgent(AgentOptions options, SimWorld world, FaceRecognizer faces) {
        super(options, signals -> RobotDriver.attach(world, RobotModels.robovie(), faces, signals));
        this.faces = faces;
    }

    public RobovieAgent(AgentOptions options, SimWorld world) {
        this(options, world, FaceRecognizer.create());
    }

    /** The recogniser, with the faces of the known users enrolled. */
    public FaceRecognizer faces() {
        return faces;
    }

    @Override protected void onConnected() {
        try {
            for (Frame user : query(FaceMemory.KNOWN_USER)) {
                enrol(user);
            }
            if (!subscribed) {
                subscribe(FaceMemory.KNOWN_USER);
                subscribed = true;
            }
            LOG.info("Robovie knows the faces of {}.", faces.names());
        } catch (AgentException e) {
            LOG.warn("Robovie cannot read the known users ({}); every face is unknown to it.", e.getMessage());
        }
    }

    @Override protected void onChanged(Message.Changed change) {
        if (enrolled.remove(change.name())) {
            faces.forget(change.name());
        }
        if (change.change() != ChangeKind.REMOVED && change.frame().isPresent()) {
            try {
                FrameText.parse(change.frame().get(), "changed " + change.name(), KnowledgeBase.create())
                        .forEach(this::enrol);
            } catch (RuntimeException e) {
                LOG.warn("Robovie cannot read the changed known user '{}': {}", change.name(), e.getMessage());
            }
        }
    }

    private void enrol(Frame user) {
        FaceMemory.face(user).ifPresent(face -> {
            faces.enroll(user.name(), face);
            enrolled.add(user.name());
        });
    }
}
