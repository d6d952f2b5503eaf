package org.kicnp.gateway;

import java.time.InstantSource;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Future;
import org.kicnp.core.BatchRejectedException;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.StaleRevisionException;
import org.kicnp.core.UnknownFrameException;
import org.kicnp.core.Value;
import org.kicnp.protocol.AgentKind;
import org.kicnp.protocol.Message.Command;
import org.kicnp.protocol.Message.Feedback;
import org.kicnp.protocol.Message.SensorSignal;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What the network puts into the knowledge base, as RUNTIME instances that slot conditions can test (section 3.3):
 * an agent's presence, the latest signal of each sensor and the latest feedback of each robot action. Frames of
 * an agent are retracted when it goes away. Classes the knowledge base lacks are added as root classes.
 */
final class RuntimeFrames {
    static final String PRESENCE = "Presence";
    static final String SENSOR_SIGNAL = "SensorSignal";
    static final String ACTION_FEEDBACK = "ActionFeedback";
    private static final Logger LOG = LoggerFactory.getLogger(RuntimeFrames.class);

    private final KnowledgeBase kb;
    private final Retraction retraction;
    private final Map<String, Set<String>> framesByAgent = new ConcurrentHashMap<>();
    private final Map<String, Expiry> expiries = new ConcurrentHashMap<>();
    /** The wall clock of the times stamped on the frames ({@link GatewayConfig#clock}). */
    private final InstantSource clock;

    RuntimeFrames(KnowledgeBase kb, Retraction retraction, InstantSource clock) {
        this.kb = kb;
        this.retraction = retraction;
        this.clock = clock;
    }

    static String presenceName(String agent) {
        return "agent_" + agent;
    }

    /** Puts the presence instance of a registered agent. */
    void present(String agent, AgentKind kind, List<String> capabilities) {
        Frame f = Frame.instance(presenceName(agent), presenceClass(kind))
                .provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("agent", DataType.STRING, Value.of(agent)))
                .slot(Slot.ofValue("kind", DataType.STRING, Value.of(kind.name().toLowerCase(Locale.ROOT))))
                .slot(Slot.ofValue("capabilities", DataType.LIST,
                        new Value.Lst(capabilities.stream().map(Value::of).toList())))
                .slot(Slot.ofValue("since", DataType.INTEGER, Value.of(clock.millis())))
                .build();
        put(agent, f);
    }

    /** Runs a task once, some milliseconds from now (on a gateway I/O thread); the future cancels it. */
    @FunctionalInterface
    interface Later {
        Future<?> run(long millis, Runnable task);
    }

    /** The expiry pending for a sensor's frame: the revision of the reading it is for, and its task. */
    private record Expiry(long revision, Future<?> task) {
    }

    /**
     * Puts the latest signal of a sensor, replacing the one before. A signal with a time to live gets the slot
     * {@code expires} (epoch milliseconds) and is retracted then (with what was derived from it), unless by then the
     * sensor's frame has changed (a newer signal, with or without a time to live of its own, replaced it).
     */
    void signal(SensorSignal s, Later later) {
        ensureClass(SENSOR_SIGNAL);
        long now = clock.millis();
        String name = "signal_" + s.source() + "_" + s.sensor();
        refuseOthers(name, s.source());
        Frame.Builder b = Frame.instance(name, SENSOR_SIGNAL)
                .provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("source", DataType.STRING, Value.of(s.source())))
                .slot(Slot.ofValue("sensor", DataType.STRING, Value.of(s.sensor())))
                .slot(Slot.ofValue("time", DataType.INTEGER, Value.of(now)))
                .slot(Slot.ofValue("values", DataType.LIST, new Value.Lst(s.values())));
        if (!s.values().isEmpty()) {
            Value first = s.values().getFirst();
            b.slot(Slot.ofValue("value", typeOf(first), first));
        }
        s.ttlMs().ifPresent(ttl -> b.slot(Slot.ofValue("expires", DataType.INTEGER, Value.of(now + ttl))));
        ChangeSet put = put(s.source(), b.build());
        // At most one expiry waits per sensor, the latest reading's: a robot that streams readings with a long time
        // to live cannot pile up timers.
        Expiry before;
        if (s.ttlMs().isPresent()) {
            long revision = put.events().isEmpty() ? kb.revision(name) : put.version();
            before = expiries.put(name, new Expiry(revision,
                    later.run(s.ttlMs().get(), () -> expire(s.source(), name, revision))));
        } else {
            before = expiries.remove(name);
        }
        if (before != null) {
            before.task().cancel(false);
        }
    }

    /**
     * Refuses to put a signal over a frame that is not this agent's: robot 'arm' sensor 'left_grip' and robot
     * 'arm_left' sensor 'grip' share the name 'signal_arm_left_grip', and one must not replace the other's reading
     * (nor retract it when it leaves).
     */
    private void refuseOthers(String name, String source) {
        if (!kb.contains(name)) {
            return;
        }
        Optional<Value> owner = kb.value(name, "source");
        if (!owner.equals(Optional.of(Value.of(source)))) {
            throw new IllegalArgumentException("its frame '" + name + "' " + owner.map(o -> "holds sensor "
                    + kb.value(name, "sensor").map(RuntimeFrames::quoted).orElse("''") + " of agent " + quoted(o))
                    .orElse("is another frame of the knowledge base") + "; rename the sensor.");
        }
    }

    private static String quoted(Value v) {
        return "'" + (v instanceof Value.Str str ? str.value() : v.toString()) + "'";
    }

    /** Expiries waiting, one at most per sensor frame. */
    int pendingExpiries() {
        return expiries.size();
    }

    /** Retracts a sensor's frame whose time to live is over, if no newer version has replaced it since. */
    private void expire(String agent, String name, long revision) {
        expiries.computeIfPresent(name, (n, e) -> e.revision() == revision ? null : e);
        try {
            if (kb.revision(name) != revision) {
                return; // replaced by a newer reading: that one's own clock runs
            }
            retraction.retract(name, revision);
        } catch (UnknownFrameException gone) {
            LOG.debug("'{}' of agent '{}' was gone when it expired.", name, agent);
        } catch (StaleRevisionException newer) {
            LOG.debug("'{}' of agent '{}' changed as it expired; the newer version stays.", name, agent);
        } catch (RuntimeException e) {
            LOG.warn("Could not retract the expired '{}' of agent '{}': {}", name, agent, e.getMessage());
        }
    }

    /**
     * Puts the latest feedback of a robot action.
     *
     * @throws IllegalArgumentException when its frame holds another action's feedback ({@link #feedbackClash})
     */
    void feedback(Command c, Feedback f) {
        feedbackClash(c).ifPresent(clash -> {
            throw new IllegalArgumentException(clash);
        });
        ensureClass(ACTION_FEEDBACK);
        Frame.Builder b = Frame.instance(feedbackName(c), ACTION_FEEDBACK)
                .provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("command", DataType.STRING, Value.of(c.id())))
                .slot(Slot.ofValue("robot", DataType.STRING, Value.of(c.robot())))
                .slot(Slot.ofValue("action", DataType.STRING, Value.of(c.action())))
                .slot(Slot.ofValue("status", DataType.STRING, Value.of(f.stage().name().toLowerCase(Locale.ROOT))))
                .slot(Slot.ofValue("detail", DataType.STRING, Value.of(f.detail())));
        f.progress().ifPresent(p -> b.slot(Slot.ofValue("progress", DataType.FLOAT, Value.of(p))));
        kb.put(b.build());
    }

    /**
     * Why a command's feedback may not go to its frame, or empty when it may. Frame names keep only letters, digits,
     * '_' and '-', so two actions can share one: 'fetch tea' and 'fetch_tea' of a robot, or robot 'arm' action
     * 'left_grip' and robot 'arm_left' action 'grip'. The first to report keeps the frame; the other would overwrite
     * its feedback, and a slot condition on it would read the wrong action's status.
     */
    Optional<String> feedbackClash(Command c) {
        String name = feedbackName(c);
        if (!kb.contains(name)) {
            return Optional.empty();
        }
        Optional<Value> robot = kb.value(name, "robot");
        Optional<Value> action = kb.value(name, "action");
        if (robot.equals(Optional.of(Value.of(c.robot()))) && action.equals(Optional.of(Value.of(c.action())))) {
            return Optional.empty();
        }
        String holder = robot.isPresent() && action.isPresent()
                ? "holds the feedback of action " + quoted(action.get()) + " of robot " + quoted(robot.get())
                : "is another frame of the knowledge base";
        return Optional.of("the feedback of action '" + c.action() + "' would go to frame '" + name + "', which "
                + holder + "; rename one of the two actions.");
    }

    private static String feedbackName(Command c) {
        return "feedback_" + c.robot() + "_" + safe(c.action());
    }

    /** Retracts the presence and sensor instances of an agent that went away. */
    void retract(String agent) {
        Set<String> names = framesByAgent.remove(agent);
        if (names == null) {
            return;
        }
        for (String name : names) {
            Expiry pending = expiries.remove(name);
            if (pending != null) {
                pending.task().cancel(false);
            }
            try {
                if (kb.contains(name)) {
                    retraction.retract(name);
                }
            } catch (RuntimeException e) {
                LOG.warn("Could not retract '{}' of agent '{}': {}", name, agent, e.getMessage());
            }
        }
    }

    private ChangeSet put(String agent, Frame f) {
        ChangeSet cs = kb.put(f);
        framesByAgent.computeIfAbsent(agent, a -> ConcurrentHashMap.newKeySet()).add(f.name());
        return cs;
    }

    private String presenceClass(AgentKind kind) {
        List<String> candidates = new ArrayList<>();
        switch (kind) {
            case ROBOT -> candidates.add("RobotAgent");
            case USER -> candidates.add("UserAgent");
            case SERVICE, PEER -> { }
        }
        candidates.add("Agent");
        for (String c : candidates) {
            if (kb.frame(c).map(Frame::isClass).orElse(false)) {
                return c;
            }
        }
        ensureClass(PRESENCE);
        return PRESENCE;
    }

    private void ensureClass(String name) {
        if (kb.contains(name)) {
            return;
        }
        try {
            kb.add(Frame.classFrame(name).provenance(Provenance.RUNTIME).build());
        } catch (BatchRejectedException e) {
            if (!kb.contains(name)) { // lost a race with another connection adding it: fine
                throw e;
            }
        }
    }

    private static DataType typeOf(Value v) {
        return v instanceof Value.Ref ? DataType.INSTANCE : v.type();
    }

    private static String safe(String action) {
        return action.replaceAll("[^\\p{L}\\p{N}_\\-]", "_");
    }
}
