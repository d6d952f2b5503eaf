package org.kicnp.inference;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.ReentrantLock;
import org.kicnp.core.Change;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameEvent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.KnowledgeListener;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
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
    private final ScriptHost scripts;
    private final Clock clock;
    private final Conditions conditions;
    private final RuleCompiler compiler;
    private final MatchNetwork network;
    private final Agenda agenda = new Agenda();
    private final Supports supports = new Supports();
    private final ActionCoordinator actions;
    private final ScriptApi scriptApi;
    private final BackwardChainer backward;
    private final Map<String, Rule> rules = new HashMap<>();
    private final Map<String, Long> stamps = new HashMap<>();
    private final List<TraceListener> tracers = new CopyOnWriteArrayList<>();
    private final ConcurrentLinkedQueue<Runnable> inbox = new ConcurrentLinkedQueue<>();
    private final ReentrantLock lock = new ReentrantLock();
    private final KnowledgeListener listener = cs -> inbox.add(() -> process(cs));
    private long stampCounter;
    private long seq;
    private long firings;
    private long names;
    private long actionIds;

    private InferenceEngine(KnowledgeBase kb, EngineOptions options, ScriptHost scripts, ActionSink sink, Clock clock) {
        this.kb = kb;
        this.options = options;
        this.scripts = scripts;
        this.clock = clock;
        this.conditions = new Conditions((f, s) -> kb.contains(f) ? kb.value(f, s) : Optional.empty());
        this.compiler = new RuleCompiler(kb);
        this.network = new MatchNetwork(kb, conditions);
        this.actions = new ActionCoordinator(kb, sink, clock, options.actionTimeout(), this::trace, this::assertFeedback);
        this.backward = new BackwardChainer(kb, options, supports, rules::get, () -> List.copyOf(rules.values()));
        this.scriptApi = new ScriptApi(kb, new ScriptApi.Services() {
            @Override public String newName(String prefix) {
                return InferenceEngine.this.newName(prefix);
            }

            @Override public String newActionId() {
                return "a" + (++actionIds);
            }

            @Override public List<Map<String, Object>> ask(String cls, Map<String, Value> bindings) {
                return InferenceEngine.this.backward.ask(cls, bindings).stream().map(Answer::toScript).toList();
            }
        });
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

        public InferenceEngine build() {
            InferenceEngine e = new InferenceEngine(kb, options, scripts, sink, clock);
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
            inbox.clear();
            for (Frame f : kb.frames()) {
                if (f.isInstance()) {
                    stamps.put(f.name(), ++stampCounter);
                }
            }
            for (Frame f : kb.frames()) {
                if (f.isClass()) {
                    install(f.name());
                }
            }
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
        lock.lock();
        try {
            int count = 0;
            Map<String, Integer> perFrame = new HashMap<>();
            while (true) {
                drain();
                actions.checkTimeouts();
                drain();
                Optional<Activation> next = agenda.poll();
                if (next.isEmpty()) {
                    actions.releaseSynchronized();
                    if (inbox.isEmpty()) {
                        return count;
                    }
                    continue;
                }
                count++;
                perFrame.merge(next.get().rule().frame(), 1, Integer::sum);
                if (count > options.maxFirings()) {
                    agenda.clear();
                    List<String> top = perFrame.entrySet().stream()
                            .sorted(Map.Entry.<String, Integer>comparingByValue().reversed()).limit(3)
                            .map(Map.Entry::getKey).toList();
                    trace(new TraceEvent.LimitReached(options.maxFirings(), top));
                    throw new InferenceLimitException(options.maxFirings(), top);
                }
                fire(next.get());
            }
        } finally {
            lock.unlock();
        }
    }

    /** Activations waiting on the agenda (after the queued changes are processed). */
    public int agendaSize() {
        lock.lock();
        try {
            drain();
            return agenda.size();
        } finally {
            lock.unlock();
        }
    }

    private void drain() {
        Runnable r;
        while ((r = inbox.poll()) != null) {
            r.run();
        }
    }

    private void process(ChangeSet cs) {
        for (FrameEvent e : cs.events()) {
            switch (e) {
                case FrameEvent.Added a -> {
                    if (a.frame().isInstance()) {
                        factAdded(a.frame());
                    } else {
                        classChanged(a.name());
                    }
                }
                case FrameEvent.Replaced r -> {
                    if (r.frame().isInstance() && r.before_().isInstance()) {
                        factReplaced(r.before_(), r.frame());
                    } else {
                        if (r.before_().isInstance()) {
                            factRemoved(r.before_());
                        }
                        classChanged(r.name());
                    }
                }
                case FrameEvent.Removed rm -> {
                    if (rm.frame().isInstance()) {
                        factRemoved(rm.frame());
                    } else {
                        uninstall(rm.name());
                    }
                }
            }
        }
    }

    // ---- facts ----

    private void factAdded(Frame f) {
        long stamp = ++stampCounter;
        stamps.put(f.name(), stamp);
        trace(new TraceEvent.FactAsserted(f.name(), f.parent().orElseThrow(), stamp));
        if (kb.contains(f.name())) {
            network.insert(f.name(), f.parent().orElseThrow()).forEach(this::consider);
        }
    }

    private void factRemoved(Frame f) {
        String name = f.name();
        trace(new TraceEvent.FactRemoved(name));
        network.retract(name);
        agenda.withdrawFact(name);
        supports.factGone(name);
        stamps.remove(name);
        Set<String> orphans = supports.closure(name);
        Optional<Derivation> d = supports.release(name);
        if (d.isPresent()) {
            boolean failed = supports.takeFailed(name);
            if (!failed) {
                kb.frame(d.get().frame()).flatMap(c -> kb.value(c.name(), "onDestroy")).ifPresent(src ->
                        runScript(d.get().frame(), "onDestroy", src.text(), snapshot(f), name, Optional.empty()));
            }
            Rule r = rules.get(d.get().frame());
            if (r != null) {
                d.get().binding().forEach((slot, fact) -> network.rematch(r.frame(), slot, fact).forEach(this::consider));
            }
        }
        retract(orphans, "it rests on '" + name + "', which was removed");
    }

    private void factReplaced(Frame before, Frame after) {
        String name = after.name();
        Set<String> changed = changedSlots(before, after);
        runDemons(before, after, changed);
        String cls = after.parent().orElseThrow();
        boolean reactive = !before.parent().equals(after.parent()) || changed.stream().anyMatch(s ->
                kb.slot(cls, s).map(e -> e.slot().reactive()).orElse(true));
        if (!reactive || !kb.contains(name)) {
            return;
        }
        trace(new TraceEvent.FactChanged(name));
        network.retract(name);
        agenda.withdrawFact(name);
        for (String dep : supports.dependentsOf(name)) {
            supports.derivation(dep).filter(d -> d.binding().containsValue(name)).ifPresent(d ->
                    failingSlot(d).ifPresent(slot -> {
                        unmarkFired(d);
                        Set<String> all = new LinkedHashSet<>(List.of(dep));
                        all.addAll(supports.closure(dep));
                        retract(all, "the condition of slot '" + slot + "' of '" + d.frame()
                                + "' no longer holds after '" + name + "' changed");
                    }));
        }
        stamps.put(name, ++stampCounter);
        network.insert(name, after.parent().orElseThrow()).forEach(this::consider);
    }

    private static Set<String> changedSlots(Frame before, Frame after) {
        Set<String> names = new LinkedHashSet<>();
        before.slots().forEach(s -> names.add(s.name()));
        after.slots().forEach(s -> names.add(s.name()));
        names.removeIf(n -> before.ownSlot(n).flatMap(Slot::effectiveValue)
                .equals(after.ownSlot(n).flatMap(Slot::effectiveValue)));
        return names;
    }

    private void runDemons(Frame before, Frame after, Set<String> changed) {
        for (String slot : changed) {
            Optional<Value> was = before.ownSlot(slot).flatMap(Slot::effectiveValue);
            Optional<Value> now = after.ownSlot(slot).flatMap(Slot::effectiveValue);
            kb.slot(after.name(), slot).ifPresent(e -> {
                Optional<String> demon = now.isPresent() ? e.slot().onAdded() : e.slot().onRemoved();
                demon.filter(src -> was.isPresent() || now.isPresent()).ifPresent(src -> runScript(e.declaredBy(),
                        now.isPresent() ? "onAdded" : "onRemoved", src, new FrameView(kb, after.name(), 0),
                        after.name(), supports.isDerived(after.name()) ? Optional.of(after.name()) : Optional.empty()));
            });
        }
    }

    // ---- rules ----

    private void classChanged(String name) {
        if (!kb.contains(name)) {
            return;
        }
        List<String> todo = new ArrayList<>(List.of(name));
        for (int i = 0; i < todo.size(); i++) {
            for (Frame c : kb.children(todo.get(i))) {
                if (c.isClass()) {
                    todo.add(c.name());
                }
            }
        }
        todo.forEach(this::install);
    }

    private void install(String frame) {
        uninstall(frame);
        compiler.compile(frame).ifPresent(r -> {
            rules.put(frame, r);
            network.addRule(r).forEach(this::consider);
        });
        for (String dep : supports.derivedFrom(frame)) {
            supports.derivation(dep).ifPresent(d -> failingSlot(d).ifPresent(slot -> {
                unmarkFired(d);
                Set<String> all = new LinkedHashSet<>(List.of(dep));
                all.addAll(supports.closure(dep));
                retract(all, "frame '" + frame + "' changed and the condition of slot '" + slot + "' no longer holds");
            }));
        }
    }

    private void uninstall(String frame) {
        if (rules.remove(frame) != null) {
            network.removeRule(frame);
            agenda.withdrawRule(frame);
        }
    }

    // ---- matching and firing ----

    private void consider(MatchNetwork.Match m) {
        Rule r = m.rule();
        String key = Activation.key(r.frame(), r, m.binding());
        if (agenda.contains(key)) {
            return;
        }
        trace(new TraceEvent.Matched(r.frame(), m.binding()));
        Optional<String> blocked = supports.blocked(r, m.binding(), key).or(() -> scriptConditionFails(r, m.binding()));
        if (blocked.isPresent()) {
            trace(new TraceEvent.Blocked(r.frame(), m.binding(), blocked.get()));
            return;
        }
        long recency = m.binding().values().stream().mapToLong(f -> stamps.getOrDefault(f, 0L)).max().orElse(0);
        agenda.add(new Activation(r, m.binding(), recency, ++seq));
        trace(new TraceEvent.Activated(r.frame(), m.binding(), agenda.size()));
    }

    private Optional<String> scriptConditionFails(Rule r, Map<String, String> binding) {
        for (SlotPattern p : r.patterns()) {
            if (p.condition() instanceof org.kicnp.core.Condition.Script s && binding.containsKey(p.slot())) {
                Map<String, Object> view = new LinkedHashMap<>();
                binding.forEach((slot, fact) -> view.put(slot, new FrameView(kb, fact, 0)));
                try {
                    Map<String, Object> g = new LinkedHashMap<>();
                    g.put("s", java.util.Collections.unmodifiableMap(view));
                    if (!scripts.test(r.frame(), p.slot(), s.source(), g)) {
                        return Optional.of("the script condition of slot '" + p.slot() + "' is false");
                    }
                } catch (RuntimeException e) {
                    trace(new TraceEvent.ScriptFailed(r.frame(), p.slot(), "", message(e)));
                    return Optional.of("the script condition of slot '" + p.slot() + "' failed: " + message(e));
                }
            }
        }
        return Optional.empty();
    }

    private void fire(Activation a) {
        Rule r = a.rule();
        Optional<String> blocked = supports.blocked(r, a.binding(), a.key());
        if (blocked.isPresent()) {
            trace(new TraceEvent.Blocked(r.frame(), a.binding(), blocked.get()));
            return;
        }
        Map<String, String> full = new LinkedHashMap<>();
        r.required().forEach(p -> full.put(p.slot(), a.binding().get(p.slot())));
        fillOptional(r, full);
        String name = newName(r.frame());
        String trigger = full.values().stream().max(java.util.Comparator.comparingLong(f -> stamps.getOrDefault(f, 0L)))
                .orElseThrow();
        Derivation d = new Derivation(name, r.frame(), full, checked(r, full), ++firings, trigger, Optional.empty());
        supports.markFired(a.key(), a.binding().values());
        supports.record(d, Optional.of(r));
        Frame.Builder b = Frame.instance(name, r.frame()).provenance(Provenance.RUNTIME);
        full.forEach((slot, fact) -> b.slot(Slot.builder(slot, DataType.INSTANCE).value(Value.ref(fact)).build()));
        try {
            kb.add(b.build());
        } catch (KnowledgeException e) {
            supports.release(name);
            trace(new TraceEvent.Blocked(r.frame(), full, "the instance could not be created: " + e.getMessage()));
            return;
        }
        trace(new TraceEvent.Fired(r.frame(), name, full, firings));
        Optional<Value> script = kb.value(name, "onInstantiate");
        if (script.isPresent() && !script.get().text().isBlank()) {
            boolean ok = runScript(r.frame(), "onInstantiate", script.get().text(), new FrameView(kb, name, 0), name,
                    Optional.of(name));
            if (!ok) {
                supports.markFailed(name);
                removeQuietly(List.of(name), "its onInstantiate script failed");
            }
        }
    }

    private void fillOptional(Rule r, Map<String, String> full) {
        for (SlotPattern p : r.optional()) {
            String best = null;
            for (String c : network.candidates(r.frame(), p.slot())) {
                if (full.containsValue(c) || (!p.shared() && supports.consumed(r.frame(), p.slot(), c))) {
                    continue;
                }
                Map<String, String> trial = new LinkedHashMap<>(full);
                trial.put(p.slot(), c);
                if (conditions.holds(p.condition(), Value.ref(c), r.frame(), trial)
                        && (best == null || stamps.getOrDefault(c, 0L) > stamps.getOrDefault(best, 0L))) {
                    best = c;
                }
            }
            if (best != null) {
                full.put(p.slot(), best);
            }
        }
    }

    private List<Derivation.CheckedCondition> checked(Rule r, Map<String, String> full) {
        List<Derivation.CheckedCondition> out = new ArrayList<>();
        for (SlotPattern p : r.patterns()) {
            String fact = full.get(p.slot());
            if (fact == null) {
                continue;
            }
            String value = switch (p.condition()) {
                case org.kicnp.core.Condition.Compare c -> conditions.follow(Value.ref(fact), c.left()).map(Value::text)
                        .orElse(fact);
                case org.kicnp.core.Condition.Between c -> conditions.follow(Value.ref(fact), c.left())
                        .map(Value::text).orElse(fact);
                case org.kicnp.core.Condition.OneOf c -> conditions.follow(Value.ref(fact), c.left()).map(Value::text)
                        .orElse(fact);
                case org.kicnp.core.Condition.Matches c -> conditions.follow(Value.ref(fact), c.left())
                        .map(Value::text).orElse(fact);
                default -> fact;
            };
            out.add(new Derivation.CheckedCondition(p.slot(), p.condition().text(), value));
        }
        return out;
    }

    /** The first slot of a derived instance whose class or condition no longer holds, if any. */
    private Optional<String> failingSlot(Derivation d) {
        Rule r = rules.get(d.frame());
        if (r == null || d.createdBy().isPresent()) {
            return Optional.empty();
        }
        for (SlotPattern p : r.patterns()) {
            String fact = d.binding().get(p.slot());
            if (fact == null) {
                if (p.required()) {
                    return Optional.of(p.slot());
                }
                continue;
            }
            if (!kb.contains(fact) || !kb.isA(fact, p.argument())
                    || !conditions.holds(p.condition(), Value.ref(fact), r.frame(), d.binding())) {
                return Optional.of(p.slot());
            }
        }
        Map<String, String> required = new LinkedHashMap<>();
        r.required().forEach(p -> required.put(p.slot(), d.binding().get(p.slot())));
        return scriptConditionFails(r, required).map(x -> "script");
    }

    private void unmarkFired(Derivation d) {
        Rule r = rules.get(d.frame());
        if (r != null) {
            supports.unmarkFired(Activation.key(r.frame(), r, d.binding()));
        }
    }

    // ---- scripts and their effects ----

    private boolean runScript(String frame, String slot, String source, Object self, String instance,
                              Optional<String> supporter) {
        List<Effect> effects = new ArrayList<>();
        trace(new TraceEvent.ScriptCalled(frame, slot, instance));
        try {
            scripts.run(frame, slot, source, scriptApi.globals(() -> self, effects, frame));
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
                    case Effect.Destroy x -> destroyNow(x.name(), "destroyed by a script of frame '" + frame + "'");
                    case Effect.Issue i -> actions.issue(new Action(i.id(), i.robot(), i.action(), i.args(), frame,
                            instance, 0));
                    case Effect.Learn l -> kb.put(l.frame());
                }
            } catch (KnowledgeException | InferenceException ex) {
                LOG.warn("An effect of a script of frame '{}' failed: {}", frame, ex.getMessage());
                trace(new TraceEvent.ScriptFailed(frame, "effect", instance, ex.getMessage()));
            }
        }
    }

    private void create(Effect.Create c, Optional<String> supporter) {
        Frame.Builder b = Frame.instance(c.name(), c.className()).provenance(Provenance.RUNTIME);
        c.slots().forEach((slot, v) -> b.slot(Slot.builder(slot, kb.slot(c.className(), slot)
                .map(e -> e.slot().type()).orElse(v.type())).value(v).build()));
        supporter.filter(kb::contains).ifPresent(s -> supports.record(new Derivation(c.name(), c.className(), Map.of(),
                List.of(), firings, s, Optional.of(s)), Optional.empty()));
        try {
            kb.add(b.build());
        } catch (KnowledgeException e) {
            supports.release(c.name());
            throw e;
        }
    }

    private static Map<String, Object> snapshot(Frame f) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put(FrameView.NAME, f.name());
        f.slots().forEach(s -> s.effectiveValue().ifPresent(v -> m.put(s.name(), v.text())));
        return java.util.Collections.unmodifiableMap(m);
    }

    // ---- truth maintenance ----

    /**
     * Destroys an instance and everything derived from it, in one batch, then runs to quiescence so
     * {@code onDestroy} scripts run and freed bindings may fire again. Returns the names removed.
     *
     * @throws UnknownFrameException when there is no such instance
     * @throws KnowledgeException when a frame the engine did not derive still refers to one of them
     */
    public Set<String> destroy(String instance) {
        lock.lock();
        try {
            drain();
            Set<String> removed = destroyNow(instance, "destroyed through the engine");
            runToQuiescence();
            return removed;
        } finally {
            lock.unlock();
        }
    }

    private Set<String> destroyNow(String instance, String reason) {
        if (!kb.frame(instance).map(Frame::isInstance).orElse(false)) {
            throw new UnknownFrameException(instance);
        }
        Set<String> all = new LinkedHashSet<>(List.of(instance));
        all.addAll(supports.closure(instance));
        all.removeIf(n -> !kb.contains(n));
        kb.apply(all.stream().map(Change.Remove::new).toList());
        all.forEach(n -> trace(new TraceEvent.Retracted(n, n.equals(instance) ? reason
                : "it rests on '" + instance + "', which was " + reason)));
        return all;
    }

    private void retract(Set<String> names, String reason) {
        removeQuietly(names, reason);
    }

    private void removeQuietly(java.util.Collection<String> names, String reason) {
        List<String> live = names.stream().filter(kb::contains).toList();
        if (live.isEmpty()) {
            return;
        }
        try {
            kb.apply(live.stream().map(Change.Remove::new).toList());
            live.forEach(n -> trace(new TraceEvent.Retracted(n, reason)));
        } catch (KnowledgeException e) {
            LOG.error("Could not retract {} ({}): {}", live, reason, e.getMessage());
        }
    }

    // ---- explanations and questions ----

    /** Why an instance exists: its derivation and, recursively, those of what it rests on, down to the stimuli. */
    public Explanation why(String instance) {
        lock.lock();
        try {
            drain();
            return why(instance, new java.util.HashSet<>());
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
            drain();
            return backward.ask(className, partialBindings);
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
                out = scripts.run(e.get().declaredBy(), slot, e.get().slot().onNeeded().get(),
                        scriptApi.globals(() -> new FrameView(kb, instance, 0), effects, e.get().declaredBy()));
            } catch (RuntimeException ex) {
                trace(new TraceEvent.ScriptFailed(e.get().declaredBy(), "onNeeded", instance, message(ex)));
                return Optional.empty();
            }
            apply(effects, e.get().declaredBy(), instance, Optional.empty());
            return out == null ? Optional.empty() : Optional.of(ScriptApi.toValue(out, e.get().slot().type()));
        } finally {
            lock.unlock();
        }
    }

    // ---- actions ----

    @Override public void actionStarted(String actionId) {
        inbox.add(() -> actions.started(actionId));
    }

    @Override public void actionEnded(String actionId, String result) {
        inbox.add(() -> actions.ended(actionId, result));
    }

    @Override public void actionFailed(String actionId, String reason) {
        inbox.add(() -> actions.failed(actionId, reason));
    }

    /** Where the action stands, if the engine issued it. */
    public Optional<Action.Status> actionStatus(String actionId) {
        lock.lock();
        try {
            drain();
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

    private void assertFeedback(ActionCoordinator.Tracked t) {
        Action a = t.action;
        Frame f = Frame.instance(FEEDBACK_CLASS + "-" + a.id(), FEEDBACK_CLASS).provenance(Provenance.RUNTIME)
                .slot(str("action", a.id())).slot(str("robot", a.robot())).slot(str("name", a.name()))
                .slot(str("status", t.status.name().toLowerCase(java.util.Locale.ROOT))).slot(str("result", t.detail))
                .slot(str("frame", a.frame())).slot(str("issuedBy", a.instance())).build();
        try {
            kb.put(f);
        } catch (KnowledgeException e) {
            LOG.warn("Could not record feedback for action '{}': {}", a.id(), e.getMessage());
        }
    }

    /**
     * The {@value #FEEDBACK_CLASS} class frame the engine adds when it is missing. Knowledge bases whose frames
     * match on feedback declare it (or add this frame) before those frames load.
     */
    public static Frame feedbackClass() {
        Frame.Builder b = Frame.classFrame(FEEDBACK_CLASS);
        for (String s : List.of("action", "robot", "name", "status", "result", "frame", "issuedBy")) {
            b.slot(Slot.builder(s, DataType.STRING).build());
        }
        return b.build();
    }

    private static Slot str(String name, String value) {
        return Slot.ofValue(name, DataType.STRING, Value.of(value));
    }

    // ---- helpers ----

    private String newName(String prefix) {
        String n;
        do {
            n = prefix + "-" + (++names);
        } while (kb.contains(n));
        return n;
    }

    private void trace(TraceEvent e) {
        for (TraceListener t : tracers) {
            try {
                t.trace(e);
            } catch (RuntimeException ex) {
                LOG.warn("Trace listener {} failed: {}", t, ex.getMessage());
            }
        }
    }

    private static String message(Throwable e) {
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    }
}
