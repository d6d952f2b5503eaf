package org.kicnp.inference;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Every way the engine calls scripts: behavior scripts ({@code onInstantiate}, {@code onDestroy}), script
 * conditions, and the FRL demons. A script's effects are collected while it runs and applied only if it succeeds.
 */
final class ScriptCalls {
    private static final Logger LOG = LoggerFactory.getLogger(ScriptCalls.class);
    /**
     * The script conditions (frame.slot) whose failure has been logged: a broken condition fails for every candidate
     * binding, so it is logged once and traced every time.
     */
    private final Set<String> conditionFailuresLogged = new HashSet<>();
    /**
     * The outcomes of script conditions that rest on one instance only, by that instance, then by frame and slot
     * (see {@link #conditionFails}): empty, the condition held; else why the binding is blocked.
     */
    private final Map<String, Map<ConditionSlot, Optional<String>>> outcomes = new HashMap<>();
    /**
     * Each script condition's text decided without GraalJS where it can be ({@link SimpleCondition}), or empty: parsed
     * once per text. A text that is not simple runs as a script, as every one did before.
     */
    private final Map<String, Optional<SimpleCondition>> simple = new HashMap<>();

    /** A script condition: the slot of a behavior frame it is written on. */
    private record ConditionSlot(String frame, String slot) {
    }

    /** What applying effects needs from the forward chainer. */
    interface Target {
        Set<String> destroy(String instance, String reason);

        long firings();
    }

    private final KnowledgeBase kb;
    private final ScriptHost host;
    private final ScriptApi scriptApi;
    private final Supports supports;
    private final ActionCoordinator actions;
    private final Consumer<TraceEvent> tracer;
    private final Target target;

    ScriptCalls(KnowledgeBase kb, ScriptHost host, ScriptApi scriptApi, Supports supports, ActionCoordinator actions,
                Consumer<TraceEvent> tracer, Target target) {
        this.kb = kb;
        this.host = host;
        this.scriptApi = scriptApi;
        this.supports = supports;
        this.actions = actions;
        this.tracer = tracer;
        this.target = target;
    }


    /** Runs a script; on success applies its effects, on failure traces it and changes nothing. */
    boolean run(String frame, String slot, String source, Object self, String instance,
                              Optional<String> supporter) {
        List<Effect> effects = new ArrayList<>();
        trace(new TraceEvent.ScriptCalled(frame, slot, instance));
        try {
            host.run(frame, slot, source, scriptApi.globals(() -> self, effects, frame));
        } catch (RuntimeException e) {
            LOG.warn("Script in slot '{}' of frame '{}' failed for '{}': {}", slot, frame, instance, message(e));
            trace(new TraceEvent.ScriptFailed(frame, slot, instance, message(e)));
            return false;
        }
        apply(effects, frame, instance, supporter);
        return true;
    }

    private void apply(List<Effect> effects, String frame, String instance, Optional<String> supporter) {
        for (Effect e : effects) {
            try {
                switch (e) {
                    case Effect.Create c -> create(c, supporter);
                    case Effect.Destroy x -> target.destroy(x.name(), "destroyed by a script of frame '" + frame + "'");
                    case Effect.Issue i -> actions.issue(action(i, frame, instance));
                    case Effect.Learn l -> learn(l.frame());
                    case Effect.Cancel c -> actions.cancelByIdOrRobot(c.target(), c.reason());
                }
            } catch (KnowledgeException | InferenceException ex) {
                LOG.warn("An effect of a script of frame '{}' failed: {}", frame, ex.getMessage());
                trace(new TraceEvent.ScriptFailed(frame, "effect", instance, ex.getMessage()));
            }
        }
    }

    /**
     * The action an issue effect stands for: the robot is the target's {@code robot} slot when it has one (a Mouth
     * names its robot), else the target itself; the timeout is the behavior frame's {@code timeout} slot (ms) when
     * it has one, else the engine's default (0 here).
     */
    private Action action(Effect.Issue i, String frame, String instance) {
        String robot = kb.contains(i.robot()) ? kb.value(i.robot(), "robot").map(Value::text).orElse(i.robot())
                : i.robot();
        long timeout = kb.contains(frame) ? kb.value(frame, "timeout")
                .map(v -> v instanceof Value.Int n ? n.value() : 0L).orElse(0L) : 0L;
        return new Action(i.id(), robot, i.robot(), i.action(), i.args(), frame, instance, timeout, 0);
    }

    /** Adds or updates a learned frame; a declared or runtime frame of that name is never overwritten. */
    private void learn(Frame f) {
        Optional<Frame> existing = kb.frame(f.name());
        if (existing.isPresent() && !existing.get().learned()) {
            throw new InferenceException("learn() cannot replace frame '" + f.name() + "': it was not learned.");
        }
        kb.put(f);
    }

    /** A derived instance was retracted: actions it issued that are still held will not be sent. */
    void retracted(String instance) {
        actions.withdraw(instance, "the instance '" + instance + "' that issued it was retracted");
    }

    private void create(Effect.Create c, Optional<String> supporter) {
        if (supporter.isPresent() && !kb.contains(supporter.get())) {
            // It would rest on an instance that is gone (destroyed by an earlier effect of the same script): an
            // orphan outliving its support, which the other order of the two calls would have retracted.
            throw new InferenceException("create('" + c.className() + "') was not applied: '" + supporter.get()
                    + "', on which it would rest, is gone (destroyed by the same script).");
        }
        Frame.Builder b = Frame.instance(c.name(), c.className()).provenance(Provenance.RUNTIME);
        c.slots().forEach((slot, v) -> b.slot(Slot.builder(slot, kb.slot(c.className(), slot)
                .map(e -> e.slot().type()).orElse(v.type())).value(v).build()));
        supporter.ifPresent(s -> supports.record(new Derivation(c.name(), c.className(), Map.of(),
                List.of(), target.firings(), s, Optional.of(s),
                supports.derivation(s).map(Derivation::depth).orElse(0) + 1), Optional.empty()));
        try {
            kb.add(b.build());
        } catch (KnowledgeException e) {
            supports.release(c.name());
            throw e;
        }
    }

    /**
     * The {@code s} of an {@code onDestroy}: a removed instance's slots as they were, own values first, then the
     * values it inherited from its class (while the class is there), as {@code s} of its other scripts has them.
     */
    Map<String, Object> snapshot(Frame f) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put(FrameView.NAME, f.name());
        f.slots().forEach(s -> s.effectiveValue().ifPresent(v -> m.put(s.name(), v.text())));
        f.parent().filter(kb::contains).ifPresent(cls -> kb.slots(cls).forEach(e -> {
            if (!m.containsKey(e.slot().name())) {
                kb.value(cls, e.slot().name()).ifPresent(v -> m.put(e.slot().name(), v.text()));
            }
        }));
        return Collections.unmodifiableMap(m);
    }

    /**
     * Gets the rules' scripts ready ahead of their first run ({@link ScriptHost#prepare}), one after another on one
     * background (platform) thread, under the ids their runs use: each frame's {@code onInstantiate} and
     * {@code onDestroy} and its script conditions. Returns at once; a firing that comes first parses its script
     * itself, as before.
     */
    void prepare(List<Rule> rules) {
        List<String[]> todo = new ArrayList<>();
        for (Rule r : rules) {
            r.onInstantiate().ifPresent(src -> todo.add(new String[] {r.frame(), "onInstantiate", src}));
            r.onDestroy().ifPresent(src -> todo.add(new String[] {r.frame(), "onDestroy", src}));
            for (SlotPattern p : r.patterns()) {
                if (p.condition() instanceof org.kicnp.core.Condition.Script s) {
                    todo.add(new String[] {r.frame(), p.slot(), s.source()});
                }
            }
        }
        if (!todo.isEmpty()) {
            // A platform thread: GraalJS supports contexts on virtual threads only experimentally (and warns so).
            Thread.ofPlatform().daemon().name("prepare-scripts").start(() -> todo.forEach(t -> host.prepare(t[0], t[1], t[2])));
        }
    }

    /**
     * Why a script condition of the binding fails, if one does: false, or it threw. A condition whose run read only its
     * own slot gave an outcome that rests on that slot's instance alone ({@link ConditionView}); it is kept for that
     * instance and frame ({@link #outcomes}) and given to every later binding with that instance in that slot, so
     * that a new instance joining many others does not run one condition per pair (Table 5's rows wait on an
     * {@code ActionFeedback} with {@code s.mDone.frame == 'X'}: each new user met every feedback there was). What the
     * outcome rests on is the instance as the knowledge base shows it; the engine forgets it when the instance, or
     * one it reads through, changes or goes ({@link #forget}) and when the frame is installed again
     * ({@link #forgetFrame}). A run that threw is not kept (a time limit may cut a run short on a busy machine). A
     * condition of the simple forms is decided without GraalJS where that gives the script's answer
     * ({@link SimpleCondition}); its outcome is kept the same way.
     */
    Optional<String> conditionFails(Rule r, Map<String, String> binding) {
        return conditionFails(r, binding, true);
    }

    /**
     * As {@link #conditionFails}, every script condition run afresh and nothing kept: what the scripts say now, for
     * {@code whyNot}, which is asked when the engine's view and the world may differ.
     */
    Optional<String> conditionFailsNow(Rule r, Map<String, String> binding) {
        return conditionFails(r, binding, false);
    }

    private Optional<String> conditionFails(Rule r, Map<String, String> binding, boolean keep) {
        for (SlotPattern p : r.patterns()) {
            if (p.condition() instanceof org.kicnp.core.Condition.Script s && binding.containsKey(p.slot())) {
                String fact = binding.get(p.slot());
                Map<ConditionSlot, Optional<String>> kept = keep ? outcomes.get(fact) : null;
                ConditionSlot at = keep ? new ConditionSlot(r.frame(), p.slot()) : null;
                Optional<String> outcome = kept == null ? null : kept.get(at);
                if (outcome == null) {
                    outcome = run(r, p.slot(), s.source(), binding, fact, at);
                }
                if (outcome.isPresent()) {
                    return outcome;
                }
            }
        }
        return Optional.empty();
    }

    /**
     * Runs one script condition for a binding; keeps the outcome under {@code at} (null: not kept) when the run read
     * only its own slot.
     */
    private Optional<String> run(Rule r, String slot, String source, Map<String, String> binding, String fact,
            ConditionSlot at) {
        ConditionView view = new ConditionView(kb, binding, slot);
        Optional<String> outcome;
        try {
            Optional<Boolean> decided = simple.computeIfAbsent(source, SimpleCondition::parse)
                    .flatMap(c -> c.test(view));
            boolean holds;
            if (decided.isPresent()) {
                holds = decided.get();
            } else {
                Map<String, Object> g = new LinkedHashMap<>();
                g.put("s", view);
                holds = host.test(r.frame(), slot, source, g);
            }
            outcome = holds ? Optional.empty() : Optional.of("the script condition of slot '" + slot + "' is false");
        } catch (RuntimeException e) {
            trace(new TraceEvent.ScriptFailed(r.frame(), slot, "", message(e)));
            if (conditionFailuresLogged.add(r.frame() + "." + slot)) {
                LOG.warn("The script condition of slot '{}' of frame '{}' failed, so it counts as false (later "
                        + "failures of it are in the trace only): {}", slot, r.frame(), message(e));
            }
            return Optional.of("the script condition of slot '" + slot + "' failed: " + message(e));
        }
        if (at != null && !view.readOther() && kb.contains(fact)) {
            outcomes.computeIfAbsent(fact, f -> new HashMap<>(4)).put(at, outcome);
        }
        return outcome;
    }

    /**
     * Forgets the kept script condition outcomes that rest on {@code instance}: it was added, changed or removed, or
     * an instance it refers to changed (the engine matches it again then).
     */
    void forget(String instance) {
        if (!outcomes.isEmpty()) { // most knowledge bases have no script condition: no look-up per event
            outcomes.remove(instance);
        }
    }

    /** Forgets the kept outcomes of a frame's script conditions: it is installed again (its scripts may differ). */
    void forgetFrame(String frame) {
        if (!outcomes.isEmpty()) {
            outcomes.values().removeIf(m -> {
                m.keySet().removeIf(k -> k.frame().equals(frame));
                return m.isEmpty();
            });
        }
    }

    /** Runs the onAdded / onRemoved demons of the slots an instance change touched. */
    void runDemons(Frame before, Frame after, Set<String> changed) {
        if (!kb.contains(after.name())) {
            return;
        }
        for (String slot : changed) {
            Optional<Value> was = before.ownSlot(slot).flatMap(Slot::effectiveValue);
            Optional<Value> now = after.ownSlot(slot).flatMap(Slot::effectiveValue);
            kb.slot(after.name(), slot).ifPresent(e -> {
                Optional<String> demon = now.isPresent() ? e.slot().onAdded() : e.slot().onRemoved();
                demon.filter(src -> was.isPresent() || now.isPresent()).ifPresent(src -> run(e.declaredBy(),
                        now.isPresent() ? "onAdded" : "onRemoved", src, new FrameView(kb, after.name(), 0),
                        after.name(), Optional.of(after.name()))); // what it creates rests on the instance
            });
        }
    }

    /**
     * Reads a slot through the engine: when it has no value and its slot has an {@code onNeeded} demon, the demon
     * computes one (it is returned, not stored).
     */
    Optional<Value> read(String instance, String slot) {
        Optional<Value> v = kb.value(instance, slot);
        if (v.isPresent()) {
            return v;
        }
        var e = kb.slot(instance, slot);
        if (e.isEmpty() || e.get().slot().onNeeded().isEmpty()) {
            return Optional.empty();
        }
        List<Effect> effects = new ArrayList<>();
        trace(new TraceEvent.ScriptCalled(e.get().declaredBy(), "onNeeded", instance));
        Object out;
        try {
            out = host.run(e.get().declaredBy(), slot, e.get().slot().onNeeded().get(),
                    scriptApi.globals(() -> new FrameView(kb, instance, 0), effects, e.get().declaredBy()));
        } catch (RuntimeException ex) {
            trace(new TraceEvent.ScriptFailed(e.get().declaredBy(), "onNeeded", instance, message(ex)));
            return Optional.empty();
        }
        Optional<Value> value;
        try {
            value = out == null ? Optional.empty() : Optional.of(ScriptApi.toValue(out, e.get().slot().type()));
        } catch (RuntimeException ex) { // a value the slot's type cannot hold: the demon failed, its effects go too
            String why = "The onNeeded demon of slot '" + slot + "' of frame '" + e.get().declaredBy()
                    + "' returned a value that slot cannot hold: " + message(ex);
            LOG.warn("{} (reading '{}')", why, instance);
            trace(new TraceEvent.ScriptFailed(e.get().declaredBy(), "onNeeded", instance, why));
            return Optional.empty();
        }
        apply(effects, e.get().declaredBy(), instance, Optional.empty());
        return value;
    }

    private void trace(TraceEvent e) {
        tracer.accept(e);
    }

    static String message(Throwable e) {
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    }
}
