package org.kicnp.inference;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.Relation;
import org.kicnp.core.SemanticLink;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Follows every issued action through its life cycle and turns the coordination links of behavior frames into
 * guarantees: succession (wait for the predecessor frames' unfinished actions to end; fail if one fails),
 * synchronization (actions of linked frames are released together at quiescence with one start time) and restriction
 * (while an action of a frame with a restriction link out of it runs, other robots' actions are held, in order).
 * Owned by the engine thread.
 */
final class ActionCoordinator {
    private static final Logger LOG = LoggerFactory.getLogger(ActionCoordinator.class);
    private final KnowledgeBase kb;
    private final ActionSink sink;
    private final Clock clock;
    private final Duration timeout;
    private final Consumer<TraceEvent> trace;
    private final Consumer<Tracked> finished;
    private final Map<String, Tracked> actions = new LinkedHashMap<>();
    /** Actions not finished yet, and those of them sent or started: the only ones time and coordination concern. */
    private final Set<Tracked> open = new LinkedHashSet<>();
    private final Set<Tracked> running = new LinkedHashSet<>();
    private long issued;
    private final List<Tracked> held = new ArrayList<>();
    private final List<Tracked> syncBuffer = new ArrayList<>();

    /** An action and where it stands. */
    static final class Tracked {
        Action action;
        Action.Status status = Action.Status.HELD;
        long deadline;
        String detail = "";
        final Set<String> waitsOn = new HashSet<>();
        final long seq;

        Tracked(Action a, long seq) {
            this.action = a;
            this.seq = seq;
        }
    }

    ActionCoordinator(KnowledgeBase kb, ActionSink sink, Clock clock, Duration timeout, Consumer<TraceEvent> trace,
                      Consumer<Tracked> finished) {
        this.kb = kb;
        this.sink = sink;
        this.clock = clock;
        this.timeout = timeout;
        this.trace = trace;
        this.finished = finished;
    }

    Optional<Action.Status> status(String id) {
        return Optional.ofNullable(actions.get(id)).map(t -> t.status);
    }

    List<Action> all() {
        return actions.values().stream().map(t -> t.action).toList();
    }

    void issue(Action a) {
        Tracked t = new Tracked(a, issued++);
        actions.put(a.id(), t);
        trace.accept(new TraceEvent.ActionIssued(a));
        Set<String> preds = related(a.frame(), Relation.Coordination.SUCCESSION, Direction.INTO);
        if (!preds.isEmpty()) {
            for (Tracked o : open) {
                if (preds.contains(o.action.frame())) {
                    t.waitsOn.add(o.action.id());
                }
            }
        }
        open.add(t);
        if (!related(a.frame(), Relation.Coordination.SYNCHRONIZATION, Direction.BOTH).isEmpty()) {
            syncBuffer.add(t);
            changed(t, Action.Status.HELD, "waiting for its synchronization group");
        } else if (!t.waitsOn.isEmpty() || restrictedByOther(t)) {
            held.add(t);
            changed(t, Action.Status.HELD, t.waitsOn.isEmpty() ? "restricted" : "after " + t.waitsOn);
        } else {
            send(t, clock.millis());
        }
    }

    /** At quiescence: release every synchronized action together, with one start time. */
    void releaseSynchronized() {
        if (syncBuffer.isEmpty()) {
            return;
        }
        long now = clock.millis();
        for (Tracked t : List.copyOf(syncBuffer)) {
            t.action = t.action.releasedAt(now);
            if (t.waitsOn.isEmpty() && !restrictedByOther(t)) {
                send(t, now);
            } else {
                held.add(t);
            }
        }
        syncBuffer.clear();
    }

    /** Fails every action of the instance that is still held (not yet sent), with the reason. */
    void withdraw(String instance, String reason) {
        for (Tracked t : List.copyOf(held)) {
            if (t.action.instance().equals(instance)) {
                held.remove(t);
                finish(t, Action.Status.FAILED, reason);
            }
        }
        for (Tracked t : List.copyOf(syncBuffer)) {
            if (t.action.instance().equals(instance)) {
                syncBuffer.remove(t);
                finish(t, Action.Status.FAILED, reason);
            }
        }
    }

    void started(String id) {
        Tracked t = known(id);
        if (t.status == Action.Status.SENT) {
            changed(t, Action.Status.STARTED, "");
        }
    }

    void ended(String id, String result) {
        finish(known(id), Action.Status.ENDED, result);
    }

    void failed(String id, String reason) {
        finish(known(id), Action.Status.FAILED, reason);
    }

    /** Times out every running action whose deadline has passed. */
    void checkTimeouts() {
        if (running.isEmpty()) {
            return;
        }
        long now = clock.millis();
        List<Tracked> overdue = new ArrayList<>();
        for (Tracked t : running) {
            if (now > t.deadline) {
                overdue.add(t);
            }
        }
        overdue.sort(Comparator.comparingLong(t -> t.seq));
        for (Tracked t : overdue) {
            if (t.status == Action.Status.SENT || t.status == Action.Status.STARTED) {
                String why = "no end reported within " + limit(t) + " ms";
                finish(t, Action.Status.TIMED_OUT, why);
                askToStop(t, "timed out: " + why); // the robot stops what the platform gave up on
            }
        }
    }

    /** The actions not finished yet, in the order they were issued; of one robot only unless {@code robot} is null. */
    List<Action.Unfinished> unfinished(String robot) {
        List<Action.Unfinished> out = new ArrayList<>();
        for (Tracked t : open) {
            if (robot == null || t.action.robot().equals(robot)) {
                out.add(new Action.Unfinished(t.action, t.status));
            }
        }
        return out;
    }

    /** A script's cancel: the action with that id, else every unfinished action of the robot of that name. */
    void cancelByIdOrRobot(String target, String reason) {
        if (actions.containsKey(target)) {
            cancel(target, reason);
            return;
        }
        List<String> ofRobot = new ArrayList<>();
        for (Tracked t : actions.values()) {
            if (!t.status.finished() && t.action.robot().equals(target)) {
                ofRobot.add(t.action.id());
            }
        }
        ofRobot.forEach(id -> cancel(id, reason));
    }

    /**
     * Cancels an action that has not finished: it fails with "cancelled: {@code reason}" (and fails what waits on it),
     * and where it was sent the robot is asked to stop. Returns false when there is no such unfinished action.
     */
    boolean cancel(String id, String reason) {
        Tracked t = actions.get(id);
        if (t == null || t.status.finished()) {
            return false;
        }
        boolean sent = t.status == Action.Status.SENT || t.status == Action.Status.STARTED;
        held.remove(t);
        syncBuffer.remove(t); // held for its synchronization group: released at quiescence unless taken out here
        finish(t, Action.Status.FAILED, "cancelled: " + reason);
        if (sent) {
            askToStop(t, reason);
        }
        return true;
    }

    private void finish(Tracked t, Action.Status status, String detail) {
        if (t.status.finished()) {
            return;
        }
        changed(t, status, detail);
        finished.accept(t);
        releaseHeld();
    }

    private void releaseHeld() {
        boolean progress = true;
        while (progress) {
            progress = false;
            for (Tracked t : List.copyOf(held)) {
                if (!held.contains(t)) {
                    continue; // finished or sent meanwhile, by the releases that finishing another one made
                }
                Optional<Tracked> bad = t.waitsOn.stream().map(actions::get)
                        .filter(o -> o.status == Action.Status.FAILED || o.status == Action.Status.TIMED_OUT).findFirst();
                if (bad.isPresent()) {
                    held.remove(t);
                    Tracked b = bad.get();
                    finish(t, Action.Status.FAILED, "predecessor action '" + b.action.id() + "' of frame '"
                            + b.action.frame() + "' " + b.status.name().toLowerCase() + ": " + b.detail);
                    progress = true;
                } else if (t.waitsOn.stream().allMatch(id -> actions.get(id).status == Action.Status.ENDED)
                        && !restrictedByOther(t)) {
                    held.remove(t);
                    send(t, t.action.startAt() > 0 ? t.action.startAt() : clock.millis());
                    progress = true;
                }
            }
        }
    }

    private void send(Tracked t, long startAt) {
        t.action = t.action.releasedAt(startAt);
        t.deadline = clock.millis() + limit(t);
        changed(t, Action.Status.SENT, "");
        try {
            sink.send(t.action);
        } catch (RuntimeException e) {
            // The firing that issued it stands; the action fails through its life cycle like one the robot failed.
            String why = "the action sink failed to send it: " + ScriptCalls.message(e);
            LOG.warn("Action '{}' ({} for robot '{}', frame '{}') failed: {}", t.action.id(), t.action.name(),
                    t.action.robot(), t.action.frame(), why, e);
            finish(t, Action.Status.FAILED, why);
        }
    }

    /** Asks the robot to stop a finished action; a sink that throws is logged, as the action is finished anyway. */
    private void askToStop(Tracked t, String reason) {
        try {
            sink.cancel(t.action, reason);
        } catch (RuntimeException e) {
            LOG.warn("The action sink failed to ask robot '{}' to stop action '{}' ({}): {}", t.action.robot(),
                    t.action.id(), reason, ScriptCalls.message(e));
        }
    }

    private long limit(Tracked t) {
        return t.action.timeoutMillis() > 0 ? t.action.timeoutMillis() : timeout.toMillis();
    }

    private boolean restrictedByOther(Tracked t) {
        for (Tracked o : running) {
            if (o != t && !o.action.robot().equals(t.action.robot())
                    && !related(o.action.frame(), Relation.Coordination.RESTRICTION, Direction.OUT_OF).isEmpty()) {
                return true;
            }
        }
        return false;
    }

    private enum Direction { INTO, OUT_OF, BOTH }

    /** Frames linked to {@code frame} by the relation, following links into it, out of it, or both. */
    private Set<String> related(String frame, Relation rel, Direction d) {
        Set<String> out = new HashSet<>();
        if (!kb.contains(frame)) {
            return out;
        }
        if (d != Direction.OUT_OF) {
            for (SemanticLink l : kb.linksInto(frame)) {
                if (l.relation().equals(rel)) {
                    out.add(l.frame());
                }
            }
        }
        if (d != Direction.INTO) {
            for (SemanticLink l : kb.linksOutOf(frame)) {
                if (l.relation().equals(rel)) {
                    out.add(l.frame());
                }
            }
        }
        return out;
    }

    private void changed(Tracked t, Action.Status s, String detail) {
        t.status = s;
        if (s == Action.Status.SENT || s == Action.Status.STARTED) {
            running.add(t);
        } else {
            running.remove(t);
        }
        if (s.finished()) {
            open.remove(t);
        }
        t.detail = detail == null ? "" : detail;
        trace.accept(new TraceEvent.ActionChanged(t.action.id(), s, t.detail));
    }

    private Tracked known(String id) {
        Tracked t = actions.get(id);
        if (t == null) {
            throw new InferenceException("Action '" + id + "' is not known to this engine.");
        }
        return t;
    }
}
