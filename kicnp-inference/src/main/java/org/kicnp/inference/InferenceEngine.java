package org.kicnp.inference;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executor;
import java.util.concurrent.locks.ReentrantLock;
import org.kicnp.core.Change;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.KnowledgeListener;
import org.kicnp.core.StaleRevisionException;
import org.kicnp.core.UnknownFrameException;
import org.kicnp.core.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The paper's inference engine. It listens to the knowledge base, matches instances against behavior frames,
 * fires them in conflict-resolution order (creating runtime instances and running their {@code onInstantiate}
 * scripts), keeps what it derived consistent with what it rests on, explains every derived instance, answers
 * questions by backward chaining and coordinates the actions that firings issue.
 *
 * <p>Threading: knowledge base events and action reports may arrive on any thread; they are queued and take effect
 * on the thread that calls {@link #runToQuiescence()}, which holds the engine's lock while it runs.
 */
public final class InferenceEngine implements ActionFeedback, AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(InferenceEngine.class);
    /** The class of the runtime instances that report finished actions, so frames can match on feedback. */
    public static final String FEEDBACK_CLASS = "ActionFeedback";

    private final KnowledgeBase kb;
    private final EngineOptions options;
    private final Supports supports;
    private final ActionCoordinator actions;
    private final BackwardChainer backward;
    private final ScriptCalls scripts;
    private final ForwardChainer forward;
    private final List<TraceListener> tracers = new CopyOnWriteArrayList<>();
    /** Held by every call that reads or changes the engine; {@link RunLoop} runs under it too. */
    private final ReentrantLock lock = new ReentrantLock();
    private final RunLoop loop;
    private final KnowledgeListener listener;
    private long actionIds;

    private InferenceEngine(KnowledgeBase kb, EngineOptions options, ScriptHost host, ActionSink sink, Clock clock,
                            Optional<Executor> runner) {
        this.kb = kb;
        this.options = options;
        FactView facts = new FactView(kb);
        this.supports = new Supports(facts);
        Conditions conditions = new Conditions(facts);
        this.actions = new ActionCoordinator(kb, sink, clock, options.actionTimeout(), this::trace,
                new ActionFeedbackFrames(kb)::assertFeedback);
        ScriptApi api = new ScriptApi(kb, new ScriptApi.Services() {
            @Override public String newName(String prefix) {
                return forward.freshName(prefix);
            }

            @Override public String newActionId() {
                return "a" + (++actionIds);
            }

            @Override public List<Map<String, Object>> ask(String cls, Map<String, Value> bindings) {
                return backward.ask(cls, bindings).stream().map(Answer::toScript).toList();
            }

            @Override public List<Action.Unfinished> unfinished(String robot) {
                return actions.unfinished(robot);
            }
        });
        Burst burst = new Burst(kb);
        ScriptHost releasing = burst.releasingBefore(host);
        this.scripts = new ScriptCalls(kb, releasing, api, supports, actions, this::trace, new ScriptCalls.Target() {
            @Override public Set<String> destroy(String instance, String reason) {
                return forward.destroyNow(instance, reason);
            }

            @Override public long firings() {
                return forward.firings();
            }
        });
        this.forward = new ForwardChainer(kb, facts, conditions, supports, scripts, this::trace, () -> !tracers.isEmpty());
        this.backward = new BackwardChainer(kb, options, supports, forward::rules, forward::rule,
                scripts::conditionFails);
        this.loop = new RunLoop(lock, options, forward, actions, burst, this::trace, runner);
        this.listener = loop::changed;
    }

    /** Starts building an engine over the knowledge base. */
    public static Builder builder(KnowledgeBase kb) {
        return new Builder(kb);
    }

    /** Builds an engine; {@link #build()} attaches it to the knowledge base and matches what is already there. */
    public static final class Builder {
        private final KnowledgeBase kb;
        private EngineOptions options = EngineOptions.defaults();
        private ScriptHost scripts = ScriptHost.NONE;
        private ActionSink sink = ActionSink.NONE;
        private Clock clock = Clock.SYSTEM;
        private Optional<Executor> runner = Optional.empty();

        private Builder(KnowledgeBase kb) {
            this.kb = requireNonNull(kb, "kb");
        }

        public Builder options(EngineOptions o) {
            this.options = requireNonNull(o, "options");
            return this;
        }

        public Builder scripts(ScriptHost s) {
            this.scripts = requireNonNull(s, "scripts");
            return this;
        }

        public Builder actionSink(ActionSink s) {
            this.sink = requireNonNull(s, "sink");
            return this;
        }

        public Builder clock(Clock c) {
            this.clock = requireNonNull(c, "clock");
            return this;
        }

        /**
         * Runs to quiescence by itself on this executor (give it a single-threaded one) whenever a change or an
         * action report arrives; without it, the owner calls {@link #runToQuiescence()}.
         */
        public Builder runOn(Executor executor) {
            this.runner = Optional.of(requireNonNull(executor, "executor"));
            return this;
        }

        public InferenceEngine build() {
            InferenceEngine e = new InferenceEngine(kb, options, scripts, sink, clock, runner);
            e.attach();
            return e;
        }
    }

    private void attach() {
        lock.lock();
        try {
            if (!kb.contains(FEEDBACK_CLASS)) {
                kb.add(feedbackClass());
            }
            kb.addListener(listener);
            loop.clearInbox();
            forward.start();
            scripts.prepare(forward.rules());
        } finally {
            lock.unlock();
        }
    }

    @Override public void close() {
        kb.removeListener(listener);
    }

    public void addTraceListener(TraceListener l) {
        tracers.add(requireNonNull(l, "listener"));
    }

    public void removeTraceListener(TraceListener l) {
        tracers.remove(l);
    }

    // ---- running ----

    /**
     * Processes every queued change and report and fires activations until nothing more fires; returns the number of
     * firings.
     *
     * @throws InferenceLimitException when the run exceeds the configured number of firings; the agenda is cleared
     */
    public int runToQuiescence() {
        return loop.run();
    }

    /**
     * Lets time-based work happen: on an engine that {@link Builder#runOn runs by itself}, schedules a run, which
     * times out overdue actions; call it from a timer. On a hand-driven engine, {@link #runToQuiescence()} does this.
     */
    public void tick() {
        loop.submit(() -> { });
    }

    /** Activations waiting on the agenda (after the queued changes are processed). */
    public int agendaSize() {
        lock.lock();
        try {
            loop.drain();
            return forward.agendaSize();
        } finally {
            lock.unlock();
        }
    }

    /**
     * The activations waiting on the agenda (after the queued changes are processed), in the order they would fire:
     * a snapshot copy taken under the engine's lock, so it can be read while the engine goes on.
     */
    public List<AgendaEntry> agenda() {
        lock.lock();
        try {
            loop.drain();
            return forward.agenda().stream().map(AgendaEntry::of).toList();
        } finally {
            lock.unlock();
        }
    }

    // ---- truth maintenance ----

    /**
     * Destroys an instance and everything derived from it, in one batch, then runs to quiescence so
     * {@code onDestroy} scripts run and freed bindings may fire again. Returns the names removed.
     *
     * @throws UnknownFrameException when there is no frame of that name
     * @throws KnowledgeException when the frame is a class frame (nothing is destroyed), or a frame the engine did not
     *                            derive still refers to one of them
     */
    public Set<String> destroy(String instance) {
        return destroy(instance, Change.ANY_REVISION, "destroyed through the engine");
    }

    /**
     * As {@link #destroy(String)}, only while the instance is still at {@code expectedRevision} (read from
     * {@link KnowledgeBase#revision}): a newer version of it stays, and so does everything else. {@code reason} is what
     * the trace and the explanations of what goes with it say (such as "expired: no newer reading within 500 ms").
     *
     * @throws StaleRevisionException when the instance changed since that revision; nothing is destroyed
     */
    public Set<String> destroy(String instance, long expectedRevision, String reason) {
        lock.lock();
        try {
            loop.drain();
            Set<String> removed = forward.destroyNow(instance, reason, expectedRevision);
            runToQuiescence();
            return removed;
        } finally {
            lock.unlock();
        }
    }

    // ---- explanations and questions ----

    /** Why an instance exists: its derivation and, recursively, those of what it rests on, down to the stimuli. */
    public Explanation why(String instance) {
        lock.lock();
        try {
            loop.drain();
            return why(instance, new HashSet<>());
        } finally {
            lock.unlock();
        }
    }

    private Explanation why(String instance, Set<String> seen) {
        Frame f = kb.frame(instance).orElseThrow(() -> new UnknownFrameException(instance));
        Optional<Derivation> d = supports.derivation(instance);
        if (d.isEmpty() || !seen.add(instance)) {
            return new Explanation.Asserted(instance, f.parent().orElse(""));
        }
        List<Explanation> sup = new ArrayList<>();
        for (String s : d.get().supports()) {
            if (kb.contains(s)) {
                sup.add(why(s, seen));
            }
        }
        return new Explanation.Derived(d.get(), sup);
    }

    /** The derivation of an instance the engine derived, if it did. */
    public Optional<Derivation> derivation(String instance) {
        lock.lock();
        try {
            return supports.derivation(instance);
        } finally {
            lock.unlock();
        }
    }

    /**
     * Every answer to "which instances of {@code className} (with these slot values) are there or could there be":
     * existing instances, then those backward chaining through behavior frames shows derivable. No side effects.
     */
    public List<Answer> ask(String className, Map<String, Value> partialBindings) {
        lock.lock();
        try {
            loop.drain();
            return backward.ask(className, partialBindings);
        } finally {
            lock.unlock();
        }
    }

    /**
     * Why a behavior frame has not fired, or not with some slots held: the instances that could fill each required
     * slot, then every binding of them (up to {@link EngineOptions#maxAnswers}) with what stops it now — a false
     * condition, refraction or a claim by an earlier firing, its place on the agenda, a false or failing script
     * condition (run as on matching: it cannot change anything) — or that nothing does. No side effects: nothing is
     * created.
     *
     * @param partialBindings slot → instance for required slots to hold fixed (an instance that cannot fill its
     *                        slot is reported among that slot's rejected candidates)
     * @throws UnknownFrameException when there is no such frame
     * @throws IllegalArgumentException when the frame is not a behavior frame (a class with a required instance
     *                                  slot), or a partial binding names a slot that is not one of its required ones
     */
    public WhyNot whyNot(String frame, Map<String, String> partialBindings) {
        requireNonNull(frame, "frame");
        requireNonNull(partialBindings, "partialBindings");
        lock.lock();
        try {
            loop.drain();
            Frame f = kb.frame(frame).orElseThrow(() -> new UnknownFrameException(frame));
            Rule r = forward.rule(frame).orElseThrow(() -> new IllegalArgumentException("Frame '" + frame + "' is "
                    + (f.isInstance() ? "an instance" : "not a behavior frame: it has no required instance slot")
                    + ", so the engine never fires it."));
            Set<BindingKey> waiting = new HashSet<>();
            for (Activation a : forward.agenda()) {
                waiting.add(a.key());
            }
            return new WhyNotCheck(kb, supports, scripts::conditionFailsNow, options.maxAnswers())
                    .check(r, partialBindings, waiting);
        } finally {
            lock.unlock();
        }
    }

    /** The proof trees of {@link #ask}. */
    public List<Proof> prove(String className, Map<String, Value> partialBindings) {
        return ask(className, partialBindings).stream().map(Answer::proof).toList();
    }

    /**
     * Reads a slot through the engine: when it has no value and its slot has an {@code onNeeded} demon, the demon
     * computes one (it is returned, not stored).
     */
    public Optional<Value> read(String instance, String slot) {
        lock.lock();
        try {
            loop.drain();
            return scripts.read(instance, slot);
        } finally {
            lock.unlock();
        }
    }

    // ---- actions ----

    @Override public void actionStarted(String actionId) {
        loop.submit(() -> actions.started(actionId));
    }

    @Override public void actionEnded(String actionId, String result) {
        loop.submit(() -> actions.ended(actionId, result));
    }

    @Override public void actionFailed(String actionId, String reason) {
        loop.submit(() -> actions.failed(actionId, reason));
    }

    /**
     * Cancels an action the engine issued that has not finished: it fails with "cancelled: {@code reason}", the
     * actions waiting on it (succession) fail too, and a robot already running it is asked to stop.
     *
     * @return false when the engine has no such unfinished action
     */
    public boolean cancelAction(String actionId, String reason) {
        lock.lock();
        try {
            loop.drain();
            boolean cancelled = actions.cancel(actionId, reason);
            runToQuiescence();
            return cancelled;
        } finally {
            lock.unlock();
        }
    }

    /** Where the action stands, if the engine issued it. */
    public Optional<Action.Status> actionStatus(String actionId) {
        lock.lock();
        try {
            loop.drain();
            return actions.status(actionId);
        } finally {
            lock.unlock();
        }
    }

    /** Every action issued so far, in order. */
    public List<Action> actions() {
        lock.lock();
        try {
            return actions.all();
        } finally {
            lock.unlock();
        }
    }

    /**
     * The {@value #FEEDBACK_CLASS} class frame the engine adds when it is missing. Knowledge bases whose frames
     * match on feedback declare it (or add this frame) before those frames load.
     */
    public static Frame feedbackClass() {
        return ActionFeedbackFrames.classFrame();
    }

    // ---- helpers ----

    private void trace(TraceEvent e) {
        for (TraceListener t : tracers) {
            try {
                t.trace(e);
            } catch (RuntimeException ex) {
                LOG.warn("Trace listener {} failed: {}", t, ex.getMessage());
            }
        }
    }
}
