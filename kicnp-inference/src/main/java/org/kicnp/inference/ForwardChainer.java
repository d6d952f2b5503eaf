package org.kicnp.inference;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.Function;
import org.kicnp.core.Change;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameEvent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.UnknownFrameException;
import org.kicnp.core.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Forward chaining and truth maintenance on the engine thread: turns knowledge base events into match network
 * updates and agenda entries, fires activations, and retracts what no longer holds. {@link InferenceEngine} owns
 * the loop and the lock; this class owns the network, the agenda and the rules.
 */
final class ForwardChainer {
    private static final Logger LOG = LoggerFactory.getLogger(ForwardChainer.class);
    private final KnowledgeBase kb;
    private final Conditions conditions;
    private final RuleCompiler compiler;
    private final MatchNetwork network;
    private final Agenda agenda;
    private final Supports supports;
    private final ScriptCalls scripts;
    private final Consumer<TraceEvent> tracer;
    private final BooleanSupplier tracing;
    private final FactView facts;
    private final Map<String, Rule> rules = new LinkedHashMap<>();
    private final MadeInstances made;
    private final DerivationCheck check;
    private long stampCounter;
    private long seq;
    private long firings;

    ForwardChainer(KnowledgeBase kb, FactView facts, Conditions conditions, Supports supports, ScriptCalls scripts,
                   Consumer<TraceEvent> tracer, BooleanSupplier tracing) {
        this.facts = facts;
        this.tracing = tracing;
        this.kb = kb;
        this.conditions = conditions;
        this.compiler = new RuleCompiler(kb);
        this.network = new MatchNetwork(kb, conditions, facts);
        this.agenda = new Agenda(facts);
        this.supports = supports;
        this.scripts = scripts;
        this.tracer = tracer;
        this.made = new MadeInstances(kb);
        this.check = new DerivationCheck(kb, conditions, scripts, supports, rules);
    }

    /** Stamps the instances there are and installs every behavior frame, matching what is already there. */
    void start() {
        for (Frame f : kb.frames()) {
            if (f.isInstance()) {
                facts.put(f).stamp = ++stampCounter;
            }
        }
        for (Frame f : kb.frames()) {
            if (f.isClass()) {
                install(f.name());
            }
        }
    }

    /** The activation whose turn has come, taken off the agenda; null when the agenda is empty. */
    Activation next() {
        return agenda.poll();
    }

    void clearAgenda() {
        agenda.clear();
    }

    int agendaSize() {
        return agenda.size();
    }

    List<Activation> agenda() {
        return agenda.inOrder();
    }

    List<Rule> rules() {
        return List.copyOf(rules.values());
    }

    /** The compiled rule of a behavior frame, if the frame is one. */
    Optional<Rule> rule(String frame) {
        return Optional.ofNullable(rules.get(frame));
    }

    long firings() {
        return firings;
    }

    /** Applies one committed batch to the network, the agenda and the truth maintenance records. */
    void process(ChangeSet cs) {
        List<String> classesRemoved = new ArrayList<>(0);
        for (int i = 0; i < cs.events().size(); i++) { // by index: an iterator per change set (per firing) is garbage
            switch (cs.events().get(i)) {
                case FrameEvent.Added a -> {
                    if (a.frame().isInstance()) {
                        factAdded(a.frame());
                    } else {
                        network.classesChanged();
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
                        network.classesChanged();
                        classChanged(r.name());
                        if (r.frame().isClass() && r.before_().isClass() && (!r.before_().parent()
                                .equals(r.frame().parent()) || !r.before_().slots().equals(r.frame().slots()))) {
                            rematchAll(kb.instancesOf(r.name()).stream().map(Frame::name).toList(),
                                    "class '" + r.name() + "' changed");
                        }
                    }
                }
                case FrameEvent.Removed rm -> {
                    if (rm.frame().isInstance()) {
                        factRemoved(rm.frame());
                    } else {
                        classesRemoved.add(rm.name());
                    }
                }
            }
        }
        // After the batch's instances: a frame removed with its instances still retracts them as its rule says
        // (their onDestroy runs), whatever order the batch named them in.
        for (String name : classesRemoved) {
            network.classesChanged();
            uninstall(name);
        }
    }

    // ---- facts ----

    private void factAdded(Frame f) {
        long stamp = ++stampCounter;
        String cls = f.parent().orElseThrow();
        FactView.Fact fact = made.take(f);
        if (fact == null) {
            fact = facts.touch(f.name());
        }
        fact.frame = f;
        fact.stamp = stamp;
        if (tracing.getAsBoolean()) {
            trace(new TraceEvent.FactAsserted(f.name(), cls, stamp));
        }
        List<MatchNetwork.Match> matches = network.insert(fact, cls);
        for (int i = 0; i < matches.size(); i++) {
            consider(matches.get(i));
        }
    }

    private void factRemoved(Frame f) {
        String name = f.name();
        trace(new TraceEvent.FactRemoved(name));
        network.retract(name);
        agenda.withdrawFact(name);
        supports.factGone(name);
        Set<String> orphans = supports.closure(name);
        Optional<Derivation> d = supports.release(name);
        if (d.isPresent()) {
            scripts.retracted(name);
            boolean failed = supports.takeFailed(name);
            Rule r = rules.get(d.get().frame());
            if (!failed) {
                Optional<String> onDestroy = r != null ? r.onDestroy() : kb.frame(d.get().frame())
                        .flatMap(c -> kb.value(c.name(), "onDestroy")).map(Value::text);
                onDestroy.ifPresent(src -> scripts.run(d.get().frame(), "onDestroy", src, scripts.snapshot(f), name,
                        Optional.empty()));
            }
            if (r != null) {
                d.get().binding().forEach((slot, fact) -> network.rematch(r.frame(), slot, fact).forEach(this::reconsider));
            }
        }
        removeQuietly(orphans, "it rests on '" + name + "', which was removed");
        facts.remove(name);
    }

    private void factReplaced(Frame before, Frame after) {
        String name = after.name();
        facts.put(after);
        Set<String> changed = changedSlots(before, after);
        scripts.runDemons(before, after, changed);
        String cls = after.parent().orElseThrow();
        boolean reactive = !before.parent().equals(after.parent()) || changed.stream().anyMatch(s ->
                kb.slot(cls, s).map(e -> e.slot().reactive()).orElse(true));
        if (!kb.contains(name)) {
            return;
        }
        if (!reactive) {
            reindex(name); // nothing is matched again, but facts that come later meet it as it is now
            return;
        }
        rematch(name, "'" + name + "' changed");
    }

    /**
     * Brings the memberships and index keys of a changed instance, and of every instance that reads it through a
     * reference, up to date without matching them again ({@link MatchNetwork#refresh}).
     */
    private void reindex(String name) {
        refresh(name);
        forEachReader(name, new LinkedHashSet<>(List.of(name)), this::refresh);
    }

    private void refresh(String name) {
        FactView.Fact f = facts.get(name);
        if (f != null && f.activations != null) {
            for (Activation a : f.activations) {
                a.changed = true; // what waits with it is checked again before it fires, not matched again now
            }
        }
        kb.frame(name).filter(Frame::isInstance).flatMap(Frame::parent).ifPresent(cls -> network.refresh(name, cls));
    }

    /**
     * Matches an instance again after it (or its class) changed: it leaves every memory, derived instances that rest
     * on it are re-checked (and retracted when a condition no longer holds), and it enters again as a recent fact.
     */
    private void rematch(String name, String why) {
        rematchOne(name, why);
        rematchReaders(name, why, new LinkedHashSet<>(List.of(name)));
    }

    /**
     * As {@link #rematch} for every instance of an edited class (they may inherit other values now), then, once
     * each, every instance that reads one of them through references.
     */
    private void rematchAll(List<String> names, String why) {
        names.forEach(n -> rematchOne(n, why));
        Set<String> seen = new LinkedHashSet<>(names);
        names.forEach(n -> rematchReaders(n, why, seen));
    }

    /**
     * A changed instance may be read through: a condition or an index path such as {@code mP.mA.key} reaches it from
     * an instance that refers to it. Every instance referring to it, directly or through others, is matched again,
     * so that indexes are rebuilt and the conditions of what was derived from them are checked again (and the
     * derived instances retracted where they no longer hold).
     */
    private void rematchReaders(String name, String why, Set<String> seen) {
        forEachReader(name, seen, r -> rematchOne(r, why + " (read through '" + r + "')"));
    }

    /**
     * Visits, once each, every instance the engine holds that refers to {@code name}, directly or through others;
     * those in {@code seen} are skipped, and each visited one is added to it.
     */
    private void forEachReader(String name, Set<String> seen, Consumer<String> visit) {
        List<String> todo = new ArrayList<>(kb.referrers(name));
        for (int i = 0; i < todo.size(); i++) {
            String r = todo.get(i);
            FactView.Fact f = facts.get(r);
            if (!seen.add(r) || f == null || f.frame == null) {
                continue;
            }
            visit.accept(r);
            todo.addAll(kb.referrers(r));
        }
    }

    private void rematchOne(String name, String why) {
        Optional<Frame> now = kb.frame(name);
        if (now.isEmpty() || !now.get().isInstance()) {
            return;
        }
        trace(new TraceEvent.FactChanged(name));
        network.retract(name);
        agenda.withdrawFact(name);
        for (String dep : supports.dependentsOf(name)) {
            supports.derivation(dep).filter(d -> d.binding().containsValue(name)).ifPresent(d ->
                    retractIfFailing(dep, d, slot -> "the condition of slot '" + slot + "' of '" + d.frame()
                            + "' no longer holds after " + why));
        }
        facts.touch(name).stamp = ++stampCounter;
        network.insert(name, now.get().parent().orElseThrow()).forEach(this::consider);
    }

    private static Set<String> changedSlots(Frame before, Frame after) {
        Set<String> names = new LinkedHashSet<>();
        before.slots().forEach(s -> names.add(s.name()));
        after.slots().forEach(s -> names.add(s.name()));
        names.removeIf(n -> before.ownSlot(n).flatMap(Slot::effectiveValue)
                .equals(after.ownSlot(n).flatMap(Slot::effectiveValue)));
        return names;
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
        Set<String> derived = supports.derivedFrom(frame);
        compiler.compile(frame).ifPresent(r -> {
            rules.put(frame, r);
            // Its slots' order and facets may have changed: before matching, what its instances fired stays
            // refracted and what they hold is claimed again; one that claims what an older one holds no longer fits.
            List<String> fired = derived.stream().filter(i -> supports.derivation(i)
                    .map(d -> d.createdBy().isEmpty()).orElse(false)).toList();
            supports.refract(r, fired);
            Map<String, String> conflicts = supports.reclaim(r, fired);
            network.addRule(r).forEach(this::consider);
            conflicts.forEach((i, why) -> {
                Set<String> all = new LinkedHashSet<>(List.of(i));
                all.addAll(supports.closure(i));
                removeQuietly(all, "frame '" + frame + "' changed and its " + why);
            });
        });
        for (String dep : derived) {
            supports.derivation(dep).ifPresent(d -> retractIfFailing(dep, d, slot -> "frame '" + frame
                    + "' changed and the condition of slot '" + slot + "' no longer holds"));
        }
    }

    private void uninstall(String frame) {
        if (rules.remove(frame) != null) {
            network.removeRule(frame);
            agenda.withdrawRule(frame);
        }
    }

    // ---- matching and firing ----

    /** Considers a binding made by a new fact: new, so it cannot be waiting on the agenda already. */
    private void consider(MatchNetwork.Match m) {
        consider(m, false);
    }

    /** Considers a binding matched again (after a claim on it was freed): it may be waiting already. */
    private void reconsider(MatchNetwork.Match m) {
        consider(m, true);
    }

    private void consider(MatchNetwork.Match m, boolean mayRepeat) {
        Rule r = m.rule();
        FactView.Fact[] refs = m.refs();
        String[] bound = new String[refs.length];
        long recency = 0;
        for (int i = 0; i < refs.length; i++) {
            bound[i] = refs[i].name;
            recency = Math.max(recency, refs[i].stamp);
        }
        BindingKey key = new BindingKey(r.frame(), bound);
        if (mayRepeat && agenda.contains(key, refs)) {
            return;
        }
        boolean tracing = this.tracing.getAsBoolean();
        if (tracing) {
            trace(new TraceEvent.Matched(r.frame(), m.binding()));
        }
        Optional<String> blocked = supports.blocked(r, bound, refs[0], key);
        if (blocked.isEmpty() && r.scripted()) {
            blocked = scripts.conditionFails(r, m.binding());
        }
        if (blocked.isPresent()) {
            trace(new TraceEvent.Blocked(r.frame(), m.binding(), blocked.get()));
            return;
        }
        Activation a = new Activation(r, bound, refs, recency, ++seq, key);
        agenda.add(a);
        if (tracing) {
            trace(new TraceEvent.Activated(r.frame(), m.binding(), agenda.size()));
        }
    }

    /**
     * Whether an activation whose turn has come may still fire: an earlier firing may have claimed one of its
     * instances or taken its key since it was made, or a non-reactive change to one of them made a condition false
     * (then it is traced as blocked, and it is not a firing). Conditions are checked again only after such a change.
     */
    boolean mayFire(Activation a) {
        Optional<String> blocked = supports.blocked(a.rule(), a.facts(), a.refs()[0], a.key());
        if (blocked.isEmpty() && a.changed) {
            blocked = check.failing(a.rule(), a.binding())
                    .map(why -> why + ": a bound instance changed while the binding waited on the agenda");
        }
        if (blocked.isPresent()) {
            trace(new TraceEvent.Blocked(a.rule().frame(), a.binding(), blocked.get()));
            return false;
        }
        return true;
    }

    /** Fires one activation that {@link #mayFire may fire}: creates the instance and runs its onInstantiate script. */
    void fire(Activation a) {
        Rule r = a.rule();
        Map<String, String> full = r.optional().isEmpty() ? a.binding() : withOptional(r, a.binding());
        FactView.Fact[] refs = a.refs();
        String trigger = newest(refs, full);
        List<Derivation.CheckedCondition> checked = CheckedConditions.of(r, full, refs, facts, conditions);
        long firing = ++firings;
        String name;
        while (true) {
            name = made.next(r.frame());
            Derivation d = new Derivation(name, r.frame(), full, checked, firing, trigger, Optional.empty());
            supports.markFired(a.key(), refs);
            FactView.Fact record = supports.record(d, r, refs);
            Slot[] slots = slotsOf(r, full, refs);
            try {
                Frame instance = Frame.instance(name, r.frame(), Provenance.RUNTIME, slots);
                if (full.size() == refs.length) {
                    // Its slots hold the required slots' facts in order: refs (shared: the activation is done with).
                    record.links = refs;
                    record.linksOf = instance;
                }
                kb.add(instance, framesOf(refs));
                made.added(record);
                break;
            } catch (KnowledgeException e) {
                supports.release(name);
                if (kb.contains(name)) {
                    continue; // a frame the engine did not make has this name: take the next one
                }
                trace(new TraceEvent.Blocked(r.frame(), full, "the instance could not be created: " + e.getMessage()));
                return;
            }
        }
        if (tracing.getAsBoolean()) {
            trace(new TraceEvent.Fired(r.frame(), name, full, firings));
        }
        Optional<String> script = r.onInstantiate();
        if (script.isPresent()) {
            boolean ok = scripts.run(r.frame(), "onInstantiate", script.get(), new FrameView(kb, name, 0), name,
                    Optional.of(name));
            if (!ok) {
                supports.markFailed(name);
                removeQuietly(List.of(name), "its onInstantiate script failed");
            }
        }
    }

    /** The slots of a firing's instance: each slot of the binding holding its instance, in the binding's order. */
    private static Slot[] slotsOf(Rule r, Map<String, String> full, FactView.Fact[] refs) {
        Slot[] slots = new Slot[full.size()];
        if (full.size() == refs.length) { // the required slots, in order: their facts' records are at hand
            List<Slot> templates = r.requiredTemplates();
            for (int i = 0; i < refs.length; i++) {
                slots[i] = templates.get(i).withValue(refs[i].ref());
            }
        } else {
            int i = 0;
            for (Map.Entry<String, String> e : full.entrySet()) {
                slots[i++] = Slot.ofValue(e.getKey(), DataType.INSTANCE, Value.ref(e.getValue()));
            }
        }
        return slots;
    }

    /** The bound facts' frames as the engine last saw them (null where it has none): those the new instance names. */
    private static Frame[] framesOf(FactView.Fact[] refs) {
        Frame[] out = new Frame[refs.length];
        for (int i = 0; i < refs.length; i++) {
            out[i] = refs[i].frame;
        }
        return out;
    }

    /** The most recently asserted instance of a binding: the required slots' records, then any optional ones. */
    private String newest(FactView.Fact[] refs, Map<String, String> full) {
        String trigger = null;
        long newest = -1;
        for (FactView.Fact f : refs) {
            if (f.stamp > newest) {
                newest = f.stamp;
                trigger = f.name;
            }
        }
        if (full.size() > refs.length) {
            for (String f : full.values()) {
                long st = facts.stamp(f);
                if (st > newest) {
                    newest = st;
                    trigger = f;
                }
            }
        }
        return trigger;
    }

    /** The binding with each optional slot bound to the newest instance that fits it, where one does. */
    private Binding withOptional(Rule r, Binding required) {
        Map<String, String> full = new LinkedHashMap<>(required);
        for (SlotPattern p : r.optional()) {
            String best = null;
            for (String c : network.candidates(r.frame(), p.slot())) {
                if (full.containsValue(c) || (p.claims() && supports.consumed(r.frame(), p.slot(), c))) {
                    continue;
                }
                Map<String, String> trial = new LinkedHashMap<>(full);
                trial.put(p.slot(), c);
                if (conditions.holds(p.condition(), Value.ref(c), r.frame(), trial)
                        && (best == null || facts.stamp(c) > facts.stamp(best))) {
                    best = c;
                }
            }
            if (best != null) {
                full.put(p.slot(), best);
            }
        }
        return Binding.copyOf(full);
    }

    /**
     * Retracts a derived instance, with what rests on it, when a slot of its derivation no longer holds; its binding
     * may then fire again. {@code reason} words the retraction from the failing slot.
     */
    private void retractIfFailing(String instance, Derivation d, Function<String, String> reason) {
        check.failingSlot(d).ifPresent(slot -> {
            check.unmarkFired(d);
            Set<String> all = new LinkedHashSet<>(List.of(instance));
            all.addAll(supports.closure(instance));
            removeQuietly(all, reason.apply(slot));
        });
    }

    // ---- truth maintenance ----

    /** Removes an instance and every live instance resting on it, in one batch; returns the names. */
    Set<String> destroyNow(String instance, String reason) {
        return destroyNow(instance, reason, Change.ANY_REVISION);
    }

    /** As {@link #destroyNow(String, String)}, only while the instance is at {@code expectedRevision}. */
    Set<String> destroyNow(String instance, String reason, long expectedRevision) {
        Frame target = kb.frame(instance).orElseThrow(() -> new UnknownFrameException(instance));
        if (!target.isInstance()) {
            throw new KnowledgeException("Frame '" + instance + "' is a class frame; only instances can be destroyed.");
        }
        Set<String> all = new LinkedHashSet<>(List.of(instance));
        all.addAll(supports.closure(instance));
        all.removeIf(n -> !kb.contains(n));
        kb.apply(all.stream().map(n -> new Change.Remove(n, n.equals(instance) ? expectedRevision
                : Change.ANY_REVISION)).toList());
        all.forEach(n -> trace(new TraceEvent.Retracted(n, n.equals(instance) ? reason
                : "it rests on '" + instance + "', which was " + reason)));
        return all;
    }

    /** Retracts the instances that are still there, in one batch, tracing each with the reason; a refusal is logged. */
    private void removeQuietly(Collection<String> names, String reason) {
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

    /** The next {@code Prefix-N} name that no frame has now (for instances that scripts create). */
    String freshName(String prefix) {
        return made.fresh(prefix);
    }

    private void trace(TraceEvent e) {
        tracer.accept(e);
    }
}
